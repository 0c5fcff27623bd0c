#include "agent/framework/ModuleSchedule.hpp"

#include <algorithm>
#include <sstream>

namespace agent::framework {

const char* threadName(ThreadId t) { return t == ThreadId::Perception ? "Perception" : "Motion"; }

Module& ModuleSchedule::add(ThreadId thread, std::unique_ptr<Module> m) {
  if (!m) throw ModuleError("ModuleSchedule::add: null module");
  threads_[static_cast<int>(thread)].push_back(std::move(m));
  return *threads_[static_cast<int>(thread)].back();
}

void ModuleSchedule::providedByProgram(ThreadId thread, SectionId s) {
  program_[static_cast<int>(thread)].push_back(s);
}

void ModuleSchedule::readByProgram(SectionId s) { program_reads_.push_back(s); }

namespace {
bool has(const std::vector<SectionId>& v, SectionId s) { return std::find(v.begin(), v.end(), s) != v.end(); }
std::string where(const Module& m, int thread) {
  return std::string("module '") + m.name() + "' (" + threadName(static_cast<ThreadId>(thread)) + " thread)";
}
}  // namespace

void ModuleSchedule::check() const {
  // Who writes each section: "module '...'" (or the program); who reads it.
  std::string writer[kNumSections];
  bool read[kNumSections] = {};
  for (SectionId s : program_reads_) read[static_cast<int>(s)] = true;
  for (int t = 0; t < 2; ++t) {
    for (SectionId s : program_[t])
      writer[static_cast<int>(s)] = std::string("the robot program (") + threadName(static_cast<ThreadId>(t)) + ")";
    for (const auto& m : threads_[t]) {
      for (SectionId s : m->writes()) {
        std::string& w = writer[static_cast<int>(s)];
        if (!w.empty())
          throw ModuleError(std::string("module '") + m->name() + "' writes section '" + sectionName(s) +
                            "', which " + w + " already writes: one provider per section");
        w = std::string("module '") + m->name() + "'";
      }
      for (const auto& list : {m->reads(), m->optionalReads(), m->usesPrevious()})
        for (SectionId s : list) read[static_cast<int>(s)] = true;
    }
  }
  for (int t = 0; t < 2; ++t) {
    const auto& list = threads_[t];
    for (size_t i = 0; i < list.size(); ++i) {
      for (SectionId s : list[i]->usesPrevious())
        if (writer[static_cast<int>(s)].empty())
          throw ModuleError(where(*list[i], t) + " uses section '" + sectionName(s) +
                            "', which no module provides: add a module that writes it, or remove the use");
      for (SectionId s : list[i]->reads()) {
        if (writer[static_cast<int>(s)].empty())
          throw ModuleError(where(*list[i], t) + " reads section '" + sectionName(s) +
                            "', which no module provides: add a module that writes it, or remove the read");
        // Provided later in the same thread only: the read would see the
        // previous cycle's value (or nothing on the first cycle).
        for (size_t j = i + 1; j < list.size(); ++j)
          if (has(list[j]->writes(), s))
            throw ModuleError(std::string("module '") + list[i]->name() + "' reads section '" + sectionName(s) +
                              "' before module '" + list[j]->name() + "', which provides it, runs (" +
                              threadName(static_cast<ThreadId>(t)) + " thread): order '" + list[j]->name() +
                              "' first");
      }
      for (SectionId s : list[i]->writes())
        if (!read[static_cast<int>(s)])
          throw ModuleError(where(*list[i], t) + " writes section '" + sectionName(s) +
                            "', which nothing reads: remove the module or the write, or add its reader");
    }
  }
}

void ModuleSchedule::run(ThreadId thread, blackboard::Blackboard& board) {
  for (auto& m : threads_[static_cast<int>(thread)]) m->run(board);
}

Module* ModuleSchedule::find(const std::string& name) const {
  for (const auto& list : threads_)
    for (const auto& m : list)
      if (name == m->name()) return m.get();
  return nullptr;
}

std::string ModuleSchedule::describe() const {
  std::ostringstream s;
  for (int t = 0; t < 2; ++t) {
    if (t) s << "; ";
    s << threadName(static_cast<ThreadId>(t)) << ":";
    const char* sep = " ";
    for (const auto& m : threads_[t]) {
      s << sep << m->name();
      sep = " -> ";
    }
  }
  return s.str();
}

}  // namespace agent::framework
