// The module framework: typed contracts (a module reads only what it
// declares, const, and writes only what it declares) and the start-up check
// of the declared reads and writes.
#include <gtest/gtest.h>

#include <string>
#include <type_traits>

#include "agent/framework/ModuleSchedule.hpp"

namespace fw = agent::framework;
namespace bb = agent::blackboard;
using fw::SectionId;
using fw::ThreadId;

namespace {

// A module stand-in with any declared lists (the schedule's view of it).
struct Fake : fw::Module {
  Fake(const char* n, std::vector<SectionId> r, std::vector<SectionId> w, std::vector<SectionId> u = {})
      : name_(n), r_(std::move(r)), w_(std::move(w)), u_(std::move(u)) {}
  const char* name() const override { return name_; }
  std::vector<SectionId> reads() const override { return r_; }
  std::vector<SectionId> optionalReads() const override { return {}; }
  std::vector<SectionId> writes() const override { return w_; }
  std::vector<SectionId> usesPrevious() const override { return u_; }
  void run(bb::Blackboard&) override { ++runs; }
  const char* name_;
  std::vector<SectionId> r_, w_, u_;
  int runs = 0;
};
std::unique_ptr<Fake> fake(const char* n, std::vector<SectionId> r, std::vector<SectionId> w,
                           std::vector<SectionId> u = {}) {
  return std::make_unique<Fake>(n, std::move(r), std::move(w), std::move(u));
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
  s.add(ThreadId::Perception, fake("vision", {SectionId::Frame}, {SectionId::Vision}));
  s.add(ThreadId::Perception, fake("team", {SectionId::Frame}, {SectionId::Team}));
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
  s.add(ThreadId::Perception, fake("vision adapter", {SectionId::Frame}, {SectionId::Vision}));
  s.add(ThreadId::Perception, fake("ball tracker", {SectionId::Vision, SectionId::Localisation}, {SectionId::Ball}));
  s.readByProgram(SectionId::Ball);
  const std::string e = checkError(s);
  EXPECT_NE(e.find("'ball tracker'"), std::string::npos) << e;
  EXPECT_NE(e.find("'localisation'"), std::string::npos) << e;
  EXPECT_NE(e.find("no module provides"), std::string::npos) << e;
  // Providing it fixes it.
  s.add(ThreadId::Motion, fake("localisation stand-in", {}, {SectionId::Localisation}));
  EXPECT_EQ(checkError(s), "");
}

TEST(ModuleSchedule, ProviderLaterInTheSameThreadIsAnOrderingError) {
  fw::ModuleSchedule s;
  s.add(ThreadId::Perception, fake("behaviour", {SectionId::Ball}, {SectionId::MotionRequest}));
  s.add(ThreadId::Perception, fake("ball tracker", {}, {SectionId::Ball}));
  const std::string e = checkError(s);
  EXPECT_NE(e.find("'behaviour' reads section 'ball' before module 'ball tracker'"), std::string::npos) << e;
}

TEST(ModuleSchedule, PreviousCycleUseMayComeFromLaterButMustExist) {
  fw::ModuleSchedule s;
  s.add(ThreadId::Perception, fake("ball tracker", {}, {SectionId::Ball}, {SectionId::Team}));
  s.readByProgram(SectionId::Ball);
  EXPECT_NE(checkError(s).find("uses section 'team', which no module provides"), std::string::npos);
  s.add(ThreadId::Perception, fake("team receive", {}, {SectionId::Team}));
  EXPECT_EQ(checkError(s), "");
}

TEST(ModuleSchedule, TwoWritersOfOneSectionAreRejected) {
  fw::ModuleSchedule s;
  s.add(ThreadId::Perception, fake("behaviour", {}, {SectionId::MotionRequest}));
  s.add(ThreadId::Motion, fake("action script", {}, {SectionId::MotionRequest}));
  const std::string e = checkError(s);
  EXPECT_NE(e.find("'action script' writes section 'motion_request'"), std::string::npos) << e;
}

TEST(ModuleSchedule, AWriteNobodyReadsIsRejected) {
  fw::ModuleSchedule s;
  s.providedByProgram(ThreadId::Motion, SectionId::Sensors);
  s.add(ThreadId::Motion, fake("motion", {SectionId::Sensors}, {SectionId::Motion, SectionId::Actuators}));
  s.add(ThreadId::Motion, fake("effector", {SectionId::Actuators}, {}));
  const std::string e = checkError(s);
  EXPECT_NE(e.find("module 'motion' (Motion thread) writes section 'motion', which nothing reads"), std::string::npos)
      << e;
  // An optional read counts as a reader.
  struct Sender : Fake {
    Sender() : Fake("team send", {}, {}) {}
    std::vector<SectionId> optionalReads() const override { return {SectionId::Motion}; }
  };
  s.add(ThreadId::Perception, std::make_unique<Sender>());
  EXPECT_EQ(checkError(s), "");
}

TEST(ModuleSchedule, RunsEachThreadsModulesInOrder) {
  fw::ModuleSchedule s;
  auto& a = static_cast<Fake&>(s.add(ThreadId::Motion, fake("motion", {}, {SectionId::Motion})));
  auto& b = static_cast<Fake&>(s.add(ThreadId::Perception, fake("behaviour", {SectionId::Motion}, {})));
  bb::Blackboard board;
  s.run(ThreadId::Motion, board);
  s.run(ThreadId::Motion, board);
  EXPECT_EQ(a.runs, 2);
  EXPECT_EQ(b.runs, 0);
  EXPECT_EQ(s.describe(), "Perception: behaviour; Motion: motion");
}
