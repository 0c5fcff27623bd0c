// libagent's own behaviour on the body side, cycle by cycle: counted chest
// clicks, limp / stiff toggles, `standing`, the head's stiffness, the long
// press (rUNSWift 2017/2018 libagent.cpp doButtons and preCallback).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "sim/bridge/LibagentBehaviour.hpp"

namespace al = common::libagent;
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

namespace {
// Runs a contact loss from `from` cycle by cycle; the body's command per sit cycle (index 0 = cycle 1).
std::vector<al::JointValues> sitFrom(LibagentBehaviour& lb, const al::JointValues& from, int cycles) {
  std::vector<al::JointValues> out;
  for (int c = 0; c < cycles; ++c) out.push_back(lb.body(from, true, false, true, from.angles));
  return out;
}
al::JointValues standCommand() {
  al::JointValues j{};
  for (int q = 0; q < al::kNumJoints; ++q) j.stiffnesses[q] = 1.0f;
  j.angles[al::Joints::LKneePitch] = j.angles[al::Joints::RKneePitch] = 0.8f;
  j.angles[al::Joints::LShoulderPitch] = j.angles[al::Joints::RShoulderPitch] = 1.5f;
  return j;
}
}  // namespace

// rUNSWift 2016's libagent sits in one phase: from the measured angles
// straight to its own sit pose at stiffness 1, head and legs over 200
// cycles, arms over 100 (twice as fast); no middle pose and no 0.2 phase.
// Then limp, as the others.
TEST(LibagentBehaviour, Release2016SitsInOnePhaseToItsOwnPose) {
  using LB = LibagentBehaviour;
  namespace J = al::Joints;
  const auto& sit = LB::sitAngles(simswift::bridge::Release::R2016);
  EXPECT_EQ(LB::sitMiddleAngles(simswift::bridge::Release::R2016), nullptr);
  // Its own pose: elbows yawed in to -120 deg (2017: -33 deg), the legs the same.
  EXPECT_NEAR(sit[J::LElbowYaw], -120.0 * M_PI / 180, 1e-6);
  EXPECT_NEAR(sit[J::LShoulderPitch], 65.0 * M_PI / 180, 1e-6);
  EXPECT_NEAR(LB::sitAngles(simswift::bridge::Release::R2017)[J::LElbowYaw], -33.0 * M_PI / 180, 1e-6);
  EXPECT_EQ(sit[J::LKneePitch], LB::sitAngles()[J::LKneePitch]);

  LibagentBehaviour lb(StartMode::Stiff, simswift::bridge::Release::R2016);
  const al::JointValues from = standCommand();
  const std::vector<al::JointValues> c = sitFrom(lb, from, 202);
  for (int n = 1; n <= 200; ++n) {
    SCOPED_TRACE("sit cycle " + std::to_string(n));
    const al::JointValues& j = c[n - 1];
    for (int q = 0; q < al::kNumJoints; ++q) ASSERT_EQ(j.stiffnesses[q], 1.0f);
    const float legs = n / 200.0f, arms = std::min(1.0f, n / 100.0f);
    EXPECT_NEAR(j.angles[J::LKneePitch], (1 - legs) * from.angles[J::LKneePitch] + legs * sit[J::LKneePitch], 1e-5);
    EXPECT_NEAR(j.angles[J::LShoulderPitch], (1 - arms) * from.angles[J::LShoulderPitch] + arms * sit[J::LShoulderPitch], 1e-5);
    EXPECT_NEAR(j.angles[J::RElbowYaw], (1 - arms) * from.angles[J::RElbowYaw] + arms * sit[J::RElbowYaw], 1e-5);
  }
  EXPECT_TRUE(lb.limp());  // cycle 201 went limp
  for (int q = 0; q < al::kNumJoints; ++q) {
    EXPECT_NEAR(c[99].angles[q], LB::isArm(q) ? sit[q] : 0.5f * (from.angles[q] + sit[q]), 1e-5) << q;
    EXPECT_EQ(c[200].stiffnesses[q], 0.0f);
    EXPECT_EQ(c[200].angles[q], sit[q]);
  }
}

// 2017 and 2018 share the two-phase sit: 200 cycles to the middle pose at
// stiffness 1, 100 to their sit pose at 0.2, then limp.
TEST(LibagentBehaviour, Releases2017And2018SitInTwoPhases) {
  using LB = LibagentBehaviour;
  namespace J = al::Joints;
  for (auto release : {simswift::bridge::Release::R2017, simswift::bridge::Release::R2018}) {
    SCOPED_TRACE(simswift::bridge::releaseYear(release));
    LibagentBehaviour lb(StartMode::Stiff, release);
    const std::vector<al::JointValues> c = sitFrom(lb, standCommand(), 301);
    const auto& middle = *LB::sitMiddleAngles(release);
    const auto& sit = LB::sitAngles(release);
    EXPECT_NEAR(c[199].angles[J::LElbowYaw], middle[J::LElbowYaw], 1e-5);
    EXPECT_EQ(c[199].stiffnesses[J::LElbowYaw], 1.0f);
    EXPECT_EQ(c[200].stiffnesses[J::LElbowYaw], 0.2f);
    EXPECT_NEAR(c[299].angles[J::LElbowYaw], sit[J::LElbowYaw], 1e-5);
    EXPECT_EQ(c[300].stiffnesses[J::LElbowYaw], 0.0f);
    EXPECT_TRUE(lb.limp());
  }
}

// 2016 has no stiffen[] slot: a STIFFEN (which its block cannot carry) is
// logged and ignored; the double chest click stiffens as in every release.
TEST(LibagentBehaviour, Release2016IsStiffenedOnlyByTheDoubleClick) {
  Cycles c;
  c.lb = LibagentBehaviour(StartMode::Limp, simswift::bridge::Release::R2016);
  LibagentBehaviour::Standing s;
  c.lb.stiffen(s);
  EXPECT_TRUE(c.lb.limp());
  EXPECT_FALSE(s.write.has_value());
  EXPECT_EQ(c.lb.takeLog().size(), 1u);
  c.run(5, false);
  for (int k = 0; k < 2; ++k) {
    c.run(10, true);
    c.run(10, false);
  }
  c.run(20, false);
  EXPECT_FALSE(c.lb.limp());
  int sets = 0;
  for (const auto& st : c.standing) sets += st.write.has_value() && *st.write;
  EXPECT_EQ(sets, 1);
}
