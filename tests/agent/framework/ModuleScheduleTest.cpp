// The module framework: typed contracts (a module reads only what it
// declares, const, and writes only what it declares) and the start-up check
// of the declared reads and writes.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <type_traits>

#include "agent/framework/ModuleSchedule.hpp"

namespace fw = agent::framework;
namespace bb = agent::blackboard;
using fw::SectionId;
using fw::ThreadId;

namespace {

using fw::IfProvided;
using fw::Reads;
using fw::UsesPrevious;
using fw::Writes;

// A module stand-in with any declared sections (the schedule's view of it):
// counts its runs, writes back what it was given.
template <class R, class W, class U = UsesPrevious<>>
struct Fake : fw::ModuleOf<R, W, U> {
  using Base = fw::ModuleOf<R, W, U>;
  explicit Fake(const char* n) : name_(n) {}
  const char* name() const override { return name_; }
  void update(const typename Base::In&, typename Base::Out&) override { ++runs; }
  const char* name_;
  int runs = 0;
};
template <class R, class W, class U = UsesPrevious<>>
std::unique_ptr<Fake<R, W, U>> fake(const char* n) {
  return std::make_unique<Fake<R, W, U>>(n);
}
std::string checkError(const fw::ModuleSchedule& s) {
  try {
    s.check();
  } catch (const fw::ModuleError& e) {
    return e.what();
  }
  return "";
}

// A typed module: ball from vision and the frame, the team as last frame.
struct Tracker : fw::ModuleOf<fw::Reads<bb::FrameInfo, bb::VisionMeasurements, fw::IfProvided<bb::FindBallInfo>>,
                              fw::Writes<bb::BallEstimate>, fw::UsesPrevious<bb::TeamInfo>> {
  const char* name() const override { return "tracker"; }
  void update(const In& in, Out& out) override {
    bb::BallEstimate& b = out.get<bb::BallEstimate>();
    b.valid = in.get<bb::VisionMeasurements>().frame_index >= 0;
    b.time_since_seen = in.get<bb::FrameInfo>().time;  // s: echoes the frame's time
    team_received = in.get<bb::TeamInfo>().received;
    ++runs;
  }
  int64_t team_received = -1;
  int runs = 0;
};

// Whether `get<S>()` exists on a module's In (const) or Out (mutable).
template <class V, class S, class = void>
struct CanGet : std::false_type {};
template <class V, class S>
struct CanGet<V, S, std::void_t<decltype(std::declval<V&>().template get<S>())>> : std::true_type {};

}  // namespace

// An undeclared section is not reachable: the contract is checked by the
// compiler, not by discipline.
static_assert(CanGet<const Tracker::In, bb::FrameInfo>::value);
static_assert(CanGet<const Tracker::In, bb::TeamInfo>::value);       // UsesPrevious
static_assert(CanGet<const Tracker::In, bb::FindBallInfo>::value);   // IfProvided
static_assert(!CanGet<const Tracker::In, bb::LocalisationEstimate>::value);
static_assert(!CanGet<const Tracker::In, bb::BallEstimate>::value);  // its own output is not an input
static_assert(!CanGet<Tracker::Out, bb::VisionMeasurements>::value);  // a read is not writable
static_assert(std::is_same_v<decltype(std::declval<const Tracker::In&>().get<bb::FrameInfo>()), const bb::FrameInfo&>);

// A class deriving from the plain Module (whose run() could write any
// section while it declares others) cannot be made: Module's constructors
// are ModuleOf's alone. (Rogue is complete, so nothing else stops it.)
struct Rogue : fw::Module {
  const char* name() const override { return "rogue"; }
  std::vector<SectionId> reads() const override { return {}; }
  std::vector<SectionId> optionalReads() const override { return {}; }
  std::vector<SectionId> writes() const override { return {}; }
  std::vector<SectionId> usesPrevious() const override { return {}; }
  void run(bb::Blackboard& b) override { b.motion_request.write({}); }
};
static_assert(!std::is_abstract_v<Rogue>);
static_assert(!std::is_default_constructible_v<Rogue>);
static_assert(std::is_default_constructible_v<Tracker>);
static_assert(!std::is_copy_constructible_v<Tracker>);  // nor a Module copied out of a real one
// In and Out are made from the Blackboard by ModuleOf only.
static_assert(!std::is_constructible_v<Tracker::In, bb::Blackboard&>);
static_assert(!std::is_constructible_v<Tracker::Out, bb::Blackboard&>);

namespace {
// Compiles case `n` of compile_fail/module_contract.cc with the build's
// compiler; returns the exit status and the compiler's messages.
int compileCase(int n, std::string* messages) {
  const std::string src = SIMSWIFT_SOURCE_DIR;
  const std::string cmd = "'" + std::string(SIMSWIFT_CXX_COMPILER) + "' -std=c++17 -fsyntax-only -x c++ '-I" + src +
                          "' -DCASE=" + std::to_string(n) + " '" + src +
                          "/tests/agent/framework/compile_fail/module_contract.cc' 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return -1;
  char buf[512];
  while (fgets(buf, sizeof buf, p)) *messages += buf;
  const int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

// What the static checks cannot ask: each way round the contract is a
// compile error, for the reason named (case 0, a proper module, compiles).
TEST(ModuleOf, EveryWayRoundTheContractIsACompileError) {
  std::string ok;
  ASSERT_EQ(compileCase(0, &ok), 0) << ok;
  const struct {
    int n;
    const char* what;
    const char* expect;
  } cases[] = {
      {1, "a plain Module writing from run()", "Module::Module()"},
      {2, "a ModuleOf overriding run()", "overriding final function"},
      {3, "writing an undeclared section", "get<agent::blackboard::MotionRequest>"},
      {4, "making its own Outputs from a Blackboard", "private within this context"},
  };
  for (const auto& c : cases) {
    std::string m;
    EXPECT_NE(compileCase(c.n, &m), 0) << c.what << " compiled";
#if defined(__GNUC__) && !defined(__clang__)
    // The reason, in GCC's words (the build's compiler is the test's).
    EXPECT_NE(m.find(c.expect), std::string::npos) << c.what << ":\n" << m;
#endif
  }
}

TEST(ModuleOf, DeclaresItsSectionsFromItsTypes) {
  Tracker t;
  EXPECT_EQ(t.reads(), (std::vector<SectionId>{SectionId::Frame, SectionId::Vision}));
  EXPECT_EQ(t.optionalReads(), (std::vector<SectionId>{SectionId::FindBall}));
  EXPECT_EQ(t.writes(), (std::vector<SectionId>{SectionId::Ball}));
  EXPECT_EQ(t.usesPrevious(), (std::vector<SectionId>{SectionId::Team}));
}

TEST(ModuleOf, RunsOnCopiesOfItsInputsAndPublishesItsOutputs) {
  fw::ModuleSchedule s;
  s.providedByProgram(ThreadId::Perception, SectionId::Frame);
  s.add(ThreadId::Perception, fake<Reads<bb::FrameInfo>, Writes<bb::VisionMeasurements>>("vision"));
  s.add(ThreadId::Perception, fake<Reads<bb::FrameInfo>, Writes<bb::TeamInfo>>("team"));
  auto& t = static_cast<Tracker&>(s.add(ThreadId::Perception, std::make_unique<Tracker>()));
  s.readByProgram(SectionId::Ball);
  ASSERT_EQ(checkError(s), "");
  bb::Blackboard board;
  bb::FrameInfo f;
  f.time = 2.5;
  board.frame.write(f);
  bb::TeamInfo team;
  team.received = 7;
  board.team.write(team);
  s.run(ThreadId::Perception, board);
  EXPECT_EQ(t.runs, 1);
  EXPECT_EQ(t.team_received, 7);
  EXPECT_DOUBLE_EQ(board.ball.read().time_since_seen, 2.5);
}

// The one list of sections gives the ids, the names and the fields alike.
TEST(Sections, IdsNamesAndFieldsComeFromTheOneList) {
  bb::Blackboard board;
  EXPECT_EQ(fw::kNumSections, 14);
  EXPECT_EQ(static_cast<int>(fw::SectionOf<bb::SensorFrame>::id), 0);
  EXPECT_EQ(static_cast<int>(fw::SectionOf<bb::ActuatorRequest>::id), fw::kNumSections - 1);
  EXPECT_STREQ(fw::sectionName(fw::SectionOf<bb::GameControllerData>::id), "game_controller");
  EXPECT_STREQ(fw::sectionName(fw::SectionOf<bb::FindBallInfo>::id), "findball");
  EXPECT_STREQ(fw::sectionName(SectionId::Actuators), "actuators");
  EXPECT_STREQ(fw::sectionName(SectionId::NUM_SECTIONS), "?");
  EXPECT_EQ(&fw::SectionOf<bb::TeamInbox>::of(board), &board.team_inbox);
  EXPECT_EQ(&fw::SectionOf<bb::MotionRequest>::of(board), &board.motion_request);
}

TEST(ModuleSchedule, ReadingASectionNobodyProvidesNamesBoth) {
  fw::ModuleSchedule s;
  s.providedByProgram(ThreadId::Perception, SectionId::Frame);
  s.add(ThreadId::Perception, fake<Reads<bb::FrameInfo>, Writes<bb::VisionMeasurements>>("vision adapter"));
  s.add(ThreadId::Perception, fake<Reads<bb::VisionMeasurements, bb::LocalisationEstimate>, Writes<bb::BallEstimate>>("ball tracker"));
  s.readByProgram(SectionId::Ball);
  const std::string e = checkError(s);
  EXPECT_NE(e.find("'ball tracker'"), std::string::npos) << e;
  EXPECT_NE(e.find("'localisation'"), std::string::npos) << e;
  EXPECT_NE(e.find("no module provides"), std::string::npos) << e;
  // Providing it fixes it.
  s.add(ThreadId::Motion, fake<Reads<>, Writes<bb::LocalisationEstimate>>("localisation stand-in"));
  EXPECT_EQ(checkError(s), "");
}

TEST(ModuleSchedule, ProviderLaterInTheSameThreadIsAnOrderingError) {
  fw::ModuleSchedule s;
  s.add(ThreadId::Perception, fake<Reads<bb::BallEstimate>, Writes<bb::MotionRequest>>("behaviour"));
  s.add(ThreadId::Perception, fake<Reads<>, Writes<bb::BallEstimate>>("ball tracker"));
  const std::string e = checkError(s);
  EXPECT_NE(e.find("'behaviour' reads section 'ball' before module 'ball tracker'"), std::string::npos) << e;
}

TEST(ModuleSchedule, PreviousCycleUseMayComeFromLaterButMustExist) {
  fw::ModuleSchedule s;
  s.add(ThreadId::Perception, fake<Reads<>, Writes<bb::BallEstimate>, UsesPrevious<bb::TeamInfo>>("ball tracker"));
  s.readByProgram(SectionId::Ball);
  EXPECT_NE(checkError(s).find("uses section 'team', which no module provides"), std::string::npos);
  s.add(ThreadId::Perception, fake<Reads<>, Writes<bb::TeamInfo>>("team receive"));
  EXPECT_EQ(checkError(s), "");
}

TEST(ModuleSchedule, TwoWritersOfOneSectionAreRejected) {
  fw::ModuleSchedule s;
  s.add(ThreadId::Perception, fake<Reads<>, Writes<bb::MotionRequest>>("behaviour"));
  s.add(ThreadId::Motion, fake<Reads<>, Writes<bb::MotionRequest>>("action script"));
  const std::string e = checkError(s);
  EXPECT_NE(e.find("'action script' writes section 'motion_request'"), std::string::npos) << e;
}

TEST(ModuleSchedule, AWriteNobodyReadsIsRejected) {
  fw::ModuleSchedule s;
  s.providedByProgram(ThreadId::Motion, SectionId::Sensors);
  s.add(ThreadId::Motion, fake<Reads<bb::SensorFrame>, Writes<bb::MotionState, bb::ActuatorRequest>>("motion"));
  s.add(ThreadId::Motion, fake<Reads<bb::ActuatorRequest>, Writes<>>("effector"));
  const std::string e = checkError(s);
  EXPECT_NE(e.find("module 'motion' (Motion thread) writes section 'motion', which nothing reads"), std::string::npos)
      << e;
  // An optional read counts as a reader.
  s.add(ThreadId::Perception, fake<Reads<IfProvided<bb::MotionState>>, Writes<>>("team send"));
  EXPECT_EQ(checkError(s), "");
}

TEST(ModuleSchedule, RunsEachThreadsModulesInOrder) {
  fw::ModuleSchedule s;
  using Motion = Fake<Reads<>, Writes<bb::MotionState>>;
  using Behaviour = Fake<Reads<bb::MotionState>, Writes<>>;
  auto& a = static_cast<Motion&>(s.add(ThreadId::Motion, std::make_unique<Motion>("motion")));
  auto& b = static_cast<Behaviour&>(s.add(ThreadId::Perception, std::make_unique<Behaviour>("behaviour")));
  bb::Blackboard board;
  s.run(ThreadId::Motion, board);
  s.run(ThreadId::Motion, board);
  EXPECT_EQ(a.runs, 2);
  EXPECT_EQ(b.runs, 0);
  EXPECT_EQ(s.describe(), "Perception: behaviour; Motion: motion");
}
