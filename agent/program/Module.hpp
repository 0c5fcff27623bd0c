// The robot code's module framework. A module declares which Blackboard
// sections it reads and which it writes (as B-Human's REQUIRES / PROVIDES
// do), and runs once per cycle of its thread. A ModuleSchedule holds the
// modules of each thread in their run order and checks at start-up that
// every section a module reads has a provider: a module, or the robot
// program itself (sensors each Motion tick, the frame each camera frame).
// Reading a section nobody provides is a ModuleError naming both the
// module and the section, never a silent zero.
//
// The standard order lives in one place: agent/program/ModuleOrder.cpp.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "agent/blackboard/Blackboard.hpp"

namespace agent::program {

// One id per Blackboard section (Blackboard.hpp lists them).
enum class SectionId : int {
  Sensors = 0,
  Frame,
  Touch,
  Vision,
  Localisation,
  Ball,
  Team,
  GameState,
  BehaviourRequest,
  Motion,
  Actuators,
  FindBall,
  NUM_SECTIONS
};
const char* sectionName(SectionId s);

enum class ThreadId : int { Perception = 0, Motion = 1 };
const char* threadName(ThreadId t);

struct ModuleError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Module {
 public:
  virtual ~Module() = default;
  virtual const char* name() const = 0;
  virtual std::vector<SectionId> reads() const = 0;
  virtual std::vector<SectionId> writes() const = 0;
  // Sections read as they were at the end of the previous cycle (B-Human's
  // USES): may be provided later in the same thread; must still be provided.
  virtual std::vector<SectionId> usesPrevious() const { return {}; }
  // One cycle of the module's thread (a Motion tick or a camera frame).
  virtual void run(blackboard::Blackboard& board) = 0;
};

class ModuleSchedule {
 public:
  // Appends `m` to `thread`'s run order.
  Module& add(ThreadId thread, std::unique_ptr<Module> m);
  // A section the robot program writes itself (e.g. Sensors, Frame) before
  // `thread`'s modules run.
  void providedByProgram(ThreadId thread, SectionId s);

  // Throws ModuleError if a module reads a section nobody provides, or a
  // section a later module of the same thread provides (while no earlier
  // module, other thread or the program does), or if two modules write the
  // same section.
  void check() const;

  // Runs `thread`'s modules in order.
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
};

}  // namespace agent::program
