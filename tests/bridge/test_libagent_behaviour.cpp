// libagent's own behaviour on the body side, cycle by cycle: counted chest
// clicks, limp / stiff toggles, `standing`, the head's stiffness, the long
// press (rUNSWift 2017/2018 libagent.cpp doButtons and preCallback).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sim/bridge/LibagentBehaviour.hpp"

namespace al = agent::libagent;
using simswift::bridge::LibagentBehaviour;
using simswift::bridge::StartMode;

namespace {

// Drives the sensor side cycle by cycle; remembers each cycle's presses.
struct Cycles {
  LibagentBehaviour lb{StartMode::Stiff};
  std::vector<al::ButtonPresses> presses;
  std::vector<LibagentBehaviour::Standing> standing;
  al::SensorValues v{};
  void run(int n, bool chest, bool bumper = false) {
    v.sensors[al::Sensors::ChestBoard_Button] = chest ? 1.0f : 0.0f;
    v.sensors[al::Sensors::LFoot_Bumper_Left] = bumper ? 1.0f : 0.0f;
    for (int i = 0; i < n; ++i) {
      LibagentBehaviour::Standing s;
      presses.push_back(lb.onSensors(v, s));
      standing.push_back(s);
    }
  }
  int cycle() const { return static_cast<int>(presses.size()); }
};

}  // namespace

TEST(LibagentBehaviour, OneClickReachesButtonPressesOnceAfterMoreThan18CyclesUp) {
  Cycles c;
  c.run(5, false);
  c.run(10, true);  // 0.1 s press
  const int release = c.cycle();  // the first cycle the button reads up
  c.run(60, false);
  for (int i = 0; i < c.cycle(); ++i) {
    // Up for 19 cycles before the check sees more than MAX_CLICK_INTERVAL (18).
    EXPECT_EQ(c.presses[i], i == release + LibagentBehaviour::kMaxClickInterval + 1 ? al::Buttons::kSingleClick : 0)
        << "cycle " << i << " (release at " << release << ")";
    EXPECT_FALSE(c.standing[i].write.has_value());
  }
}

TEST(LibagentBehaviour, DoubleClickTogglesLimpAndStiffWithStanding) {
  Cycles c;
  EXPECT_FALSE(c.lb.limp());
  for (int k = 0; k < 2; ++k) {
    c.run(10, true);
    c.run(10, false);  // 10 cycles up: within the series
  }
  c.run(30, false);
  EXPECT_TRUE(c.lb.limp());
  for (al::ButtonPresses p : c.presses) EXPECT_EQ(p, 0) << "libagent keeps 2 clicks";
  // Limp: the sit angles at stiffness 0, whatever the program sends.
  al::JointValues program{};
  for (int j = 0; j < al::kNumJoints; ++j) program.stiffnesses[j] = 1.0f;
  al::JointValues body = c.lb.body(program, true, false, false, program.angles);
  for (int j = 0; j < al::kNumJoints; ++j) {
    EXPECT_EQ(body.stiffnesses[j], 0.0f);
    EXPECT_EQ(body.angles[j], LibagentBehaviour::sitAngles()[j]);
  }
  // A second double click: stiff again, `standing` set once.
  c.standing.clear();
  for (int k = 0; k < 2; ++k) {
    c.run(10, true);
    c.run(10, false);
  }
  c.run(30, false);
  EXPECT_FALSE(c.lb.limp());
  int set = 0;
  for (const auto& s : c.standing) set += s.write.has_value() && *s.write;
  EXPECT_EQ(set, 1);
  // While `standing` is set the body is still limp; once cleared, obeyed.
  EXPECT_EQ(c.lb.body(program, true, true, false, program.angles).stiffnesses[0], 0.0f);
  EXPECT_EQ(c.lb.body(program, true, false, false, program.angles).stiffnesses[0], 1.0f);
}

TEST(LibagentBehaviour, DoubleClickWithAFootBumperHeldTogglesOnlyTheHead) {
  Cycles c;
  for (int k = 0; k < 2; ++k) {
    c.run(10, true, true);
    c.run(10, false, true);
  }
  c.run(30, false, true);
  EXPECT_FALSE(c.lb.limp());
  EXPECT_TRUE(c.lb.headLimp());
  al::JointValues program{};
  for (int j = 0; j < al::kNumJoints; ++j) program.stiffnesses[j] = 1.0f;
  const al::JointValues body = c.lb.body(program, true, false, false, program.angles);
  EXPECT_EQ(body.stiffnesses[al::Joints::HeadYaw], 0.0f);
  EXPECT_EQ(body.stiffnesses[al::Joints::HeadPitch], 0.0f);
  EXPECT_EQ(body.stiffnesses[al::Joints::LKneePitch], 1.0f);
}

TEST(LibagentBehaviour, ThreeAndFourClicksAndALongPressAreLibagentsOwn) {
  for (int clicks : {3, 4}) {
    Cycles c;
    for (int k = 0; k < clicks; ++k) {
      c.run(10, true);
      c.run(10, false);
    }
    c.run(30, false);
    for (al::ButtonPresses p : c.presses) EXPECT_EQ(p, 0) << clicks << " clicks";
    const std::vector<std::string> log = c.lb.takeLog();
    ASSERT_EQ(log.size(), 1u);
    EXPECT_NE(log[0].find(std::to_string(clicks) + " chest clicks"), std::string::npos) << log[0];
  }
  Cycles c;
  c.run(320, true);  // 3.2 s
  c.run(40, false);
  for (al::ButtonPresses p : c.presses) EXPECT_EQ(p, 0);
  const std::vector<std::string> log = c.lb.takeLog();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find("held 3 s"), std::string::npos) << log[0];
  // A later single click still counts.
  c.run(10, true);
  c.run(30, false);
  int ones = 0;
  for (al::ButtonPresses p : c.presses) ones += p == al::Buttons::kSingleClick;
  EXPECT_EQ(ones, 1);
}

TEST(LibagentBehaviour, HeadTouchesNeverReachButtonPresses) {
  Cycles c;
  for (int s : {al::Sensors::Head_Touch_Front, al::Sensors::Head_Touch_Middle, al::Sensors::Head_Touch_Rear}) {
    c.v.sensors[s] = 1.0f;
    c.run(20, false);
    c.v.sensors[s] = 0.0f;
    c.run(30, false);
  }
  for (al::ButtonPresses p : c.presses) EXPECT_EQ(p, 0);
}

TEST(LibagentBehaviour, StartLimpUntilStiffenThenStandingOnce) {
  LibagentBehaviour lb(StartMode::Limp);
  EXPECT_TRUE(lb.limp());
  al::JointValues program{};
  for (int j = 0; j < al::kNumJoints; ++j) program.stiffnesses[j] = 1.0f;
  EXPECT_EQ(lb.body(program, true, false, false, program.angles).stiffnesses[3], 0.0f);
  LibagentBehaviour::Standing s;
  lb.stiffen(s);
  EXPECT_FALSE(lb.limp());
  ASSERT_TRUE(s.write.has_value());
  EXPECT_TRUE(*s.write);
  // Stiff start: the program's command... before its first one, the scenario posture.
  LibagentBehaviour stiff(StartMode::Stiff);
  EXPECT_EQ(stiff.body(program, false, true, false, program.angles).stiffnesses[3], 1.0f);
}
