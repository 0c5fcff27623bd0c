// The module framework: declared reads and writes are checked at start-up.
#include <gtest/gtest.h>

#include <string>

#include "agent/program/Module.hpp"

namespace ap = agent::program;
using ap::SectionId;
using ap::ThreadId;

namespace {
struct Fake : ap::Module {
  Fake(const char* n, std::vector<SectionId> r, std::vector<SectionId> w, std::vector<SectionId> u = {})
      : name_(n), r_(std::move(r)), w_(std::move(w)), u_(std::move(u)) {}
  const char* name() const override { return name_; }
  std::vector<SectionId> reads() const override { return r_; }
  std::vector<SectionId> writes() const override { return w_; }
  std::vector<SectionId> usesPrevious() const override { return u_; }
  void run(agent::blackboard::Blackboard&) override { ++runs; }
  const char* name_;
  std::vector<SectionId> r_, w_, u_;
  int runs = 0;
};
std::unique_ptr<Fake> fake(const char* n, std::vector<SectionId> r, std::vector<SectionId> w,
                           std::vector<SectionId> u = {}) {
  return std::make_unique<Fake>(n, std::move(r), std::move(w), std::move(u));
}
std::string checkError(const ap::ModuleSchedule& s) {
  try {
    s.check();
  } catch (const ap::ModuleError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(ModuleSchedule, ReadingASectionNobodyProvidesNamesBoth) {
  ap::ModuleSchedule s;
  s.providedByProgram(ThreadId::Perception, SectionId::Frame);
  s.add(ThreadId::Perception, fake("vision adapter", {SectionId::Frame}, {SectionId::Vision}));
  s.add(ThreadId::Perception, fake("ball tracker", {SectionId::Vision, SectionId::Localisation}, {SectionId::Ball}));
  const std::string e = checkError(s);
  EXPECT_NE(e.find("'ball tracker'"), std::string::npos) << e;
  EXPECT_NE(e.find("'localisation'"), std::string::npos) << e;
  EXPECT_NE(e.find("no module provides"), std::string::npos) << e;
  // Providing it fixes it.
  s.add(ThreadId::Motion, fake("localisation stand-in", {}, {SectionId::Localisation}));
  EXPECT_EQ(checkError(s), "");
}

TEST(ModuleSchedule, ProviderLaterInTheSameThreadIsAnOrderingError) {
  ap::ModuleSchedule s;
  s.add(ThreadId::Perception, fake("behaviour", {SectionId::Ball}, {SectionId::BehaviourRequest}));
  s.add(ThreadId::Perception, fake("ball tracker", {}, {SectionId::Ball}));
  const std::string e = checkError(s);
  EXPECT_NE(e.find("'behaviour' reads section 'ball' before module 'ball tracker'"), std::string::npos) << e;
}

TEST(ModuleSchedule, PreviousCycleUseMayComeFromLaterButMustExist) {
  ap::ModuleSchedule s;
  s.add(ThreadId::Perception, fake("ball tracker", {}, {SectionId::Ball}, {SectionId::Team}));
  EXPECT_NE(checkError(s).find("uses section 'team', which no module provides"), std::string::npos);
  s.add(ThreadId::Perception, fake("team receive", {}, {SectionId::Team}));
  EXPECT_EQ(checkError(s), "");
}

TEST(ModuleSchedule, TwoWritersOfOneSectionAreRejected) {
  ap::ModuleSchedule s;
  s.add(ThreadId::Perception, fake("behaviour", {}, {SectionId::BehaviourRequest}));
  s.add(ThreadId::Motion, fake("action script", {}, {SectionId::BehaviourRequest}));
  const std::string e = checkError(s);
  EXPECT_NE(e.find("'action script' writes section 'behaviour request'"), std::string::npos) << e;
}

TEST(ModuleSchedule, RunsEachThreadsModulesInOrder) {
  ap::ModuleSchedule s;
  auto& a = static_cast<Fake&>(s.add(ThreadId::Motion, fake("touch", {}, {SectionId::Touch})));
  auto& b = static_cast<Fake&>(s.add(ThreadId::Perception, fake("behaviour", {SectionId::Touch}, {})));
  agent::blackboard::Blackboard board;
  s.run(ThreadId::Motion, board);
  s.run(ThreadId::Motion, board);
  EXPECT_EQ(a.runs, 2);
  EXPECT_EQ(b.runs, 0);
  EXPECT_EQ(s.describe(), "Perception: behaviour; Motion: touch");
}
