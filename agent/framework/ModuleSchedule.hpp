// The modules of each thread in their run order, and the start-up check of
// their contracts: every section a module reads has a provider (a module,
// or the robot program itself: sensors each Motion tick, the frame each
// camera frame) that runs before it, one provider per section, and every
// section a module writes has a reader (a module, or the program: the
// simulator-side tools that watch a section). A broken contract is a
// ModuleError naming the modules and the section, never a silent zero.
//
// The standard order lives in one place: agent/program/ModuleOrder.cpp.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "agent/framework/Module.hpp"

namespace agent::framework {

class ModuleSchedule {
 public:
  // Appends `m` to `thread`'s run order.
  Module& add(ThreadId thread, std::unique_ptr<Module> m);
  // A section the robot program writes itself (e.g. sensors, frame) before
  // `thread`'s modules run.
  void providedByProgram(ThreadId thread, SectionId s);
  // A section read from outside the modules (the program, a view).
  void readByProgram(SectionId s);

  // Throws ModuleError if a module reads a section nobody provides, or a
  // section a later module of the same thread provides (while no earlier
  // module, other thread or the program does), if two modules write the
  // same section, or if a module writes a section nobody reads.
  void check() const;

  // Runs `thread`'s modules in order on `board`.
  void run(ThreadId thread, blackboard::Blackboard& board);

  const std::vector<std::unique_ptr<Module>>& modules(ThreadId thread) const {
    return threads_[static_cast<int>(thread)];
  }
  // The module of that name (null if none).
  Module* find(const std::string& name) const;
  // "Perception: vision -> localisation -> ...; Motion: ..."
  std::string describe() const;

 private:
  std::vector<std::unique_ptr<Module>> threads_[2];
  std::vector<SectionId> program_[2];
  std::vector<SectionId> program_reads_;
};

}  // namespace agent::framework
