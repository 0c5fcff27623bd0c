// The clipper, the head, the kick's and get-ups' shapes, and the Motion
// tick's mode logic driven with synthetic sensors (no physics).
// Units: rad, s, mm.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "agent/motion/ActionMotion.hpp"

using namespace agent::motion;
namespace J = common::libagent::Joints;
namespace S = common::libagent::Sensors;
namespace bb = agent::blackboard;

namespace {

// A deterministic LCG in [0, 1) (the test owns its randomness).
struct Lcg {
  uint64_t x;
  double next() {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(x >> 11) * (1.0 / 9007199254740992.0);
  }
};

common::libagent::SensorValues standingSensors(const common::libagent::JointValues& joints) {
  common::libagent::SensorValues s{};
  s.joints = joints;
  for (int i = 0; i < 4; ++i) {
    s.sensors[S::LFoot_FSR_FrontLeft + i] = 0.66f;  // kg: 5.3 kg over eight sensors
    s.sensors[S::RFoot_FSR_FrontLeft + i] = 0.66f;
  }
  return s;
}

void expectWithinLimits(const common::libagent::JointValues& cmd, const float* prev) {
  const auto& lim = jointLimits();
  for (int i = 0; i < common::libagent::kNumJoints; ++i) {
    ASSERT_GE(cmd.angles[i], lim[i].lower) << J::kNames[i];
    ASSERT_LE(cmd.angles[i], lim[i].upper) << J::kNames[i];
    if (prev) {
      ASSERT_LE(std::fabs(cmd.angles[i] - prev[i]), lim[i].max_velocity * kMotionTick + 1e-6) << J::kNames[i];
    }
  }
}

}  // namespace

TEST(Clipper, NeverExceedsLimitsOrPerTickSpeed) {
  Clipper clip;
  Lcg rng{42};
  common::libagent::JointValues sensed{};
  float prev[common::libagent::kNumJoints];
  bool have_prev = false;
  for (int t = 0; t < 5000; ++t) {
    common::libagent::JointValues cmd{};
    for (int i = 0; i < common::libagent::kNumJoints; ++i) {
      // Wild commands: far outside the limits, occasionally NaN.
      cmd.angles[i] = static_cast<float>((rng.next() - 0.5) * 10.0);
      if (rng.next() < 0.01) cmd.angles[i] = NAN;
      cmd.stiffnesses[i] = static_cast<float>((rng.next() - 0.3) * 3);
      sensed.angles[i] = static_cast<float>((rng.next() - 0.5) * 10.0);
    }
    clip.clip(cmd, sensed);
    expectWithinLimits(cmd, have_prev ? prev : nullptr);
    for (int i = 0; i < common::libagent::kNumJoints; ++i) {
      ASSERT_TRUE(std::isfinite(cmd.angles[i]));
      ASSERT_TRUE(cmd.stiffnesses[i] == -1.0f || (cmd.stiffnesses[i] >= 0 && cmd.stiffnesses[i] <= 1));
      prev[i] = cmd.angles[i];
    }
    have_prev = true;
  }
}

TEST(Clipper, FirstCommandStartsFromSensedAngles) {
  Clipper clip;
  common::libagent::JointValues sensed{}, cmd{};
  sensed.angles[J::LKneePitch] = 1.0f;
  cmd.angles[J::LKneePitch] = 0.0f;
  clip.clip(cmd, sensed);
  EXPECT_NEAR(cmd.angles[J::LKneePitch], 1.0 - 6.402 * 0.01, 1e-4);
}

TEST(Head, SpeedLimitedAbsoluteAndRelative) {
  HeadGenerator head;
  common::libagent::SensorValues s{};
  common::libagent::JointValues out{};
  bb::HeadCommand cmd;
  cmd.yaw = 1.0f;
  cmd.yaw_speed = 0.5f;  // rad/s
  for (int i = 0; i < 100; ++i) head.tick(cmd, 1, s, 0.01, out);
  EXPECT_NEAR(out.angles[J::HeadYaw], 0.5, 1e-4);  // 1 s at 0.5 rad/s
  for (int i = 0; i < 200; ++i) head.tick(cmd, 1, s, 0.01, out);
  EXPECT_NEAR(out.angles[J::HeadYaw], 1.0, 1e-5);
  // Relative: +0.3 from the measured angle, applied once per request.
  s.joints.angles[J::HeadYaw] = 1.0f;
  cmd.relative = true;
  cmd.yaw = 0.3f;
  cmd.yaw_speed = 100.0f;  // capped at the joint's 8.268 rad/s
  head.tick(cmd, 2, s, 0.01, out);
  EXPECT_NEAR(out.angles[J::HeadYaw], 1.0 + 0.08268, 1e-4);
  for (int i = 0; i < 10; ++i) head.tick(cmd, 2, s, 0.01, out);
  EXPECT_NEAR(out.angles[J::HeadYaw], 1.3, 1e-5);
  EXPECT_NEAR(head.targetYaw(), 1.3, 1e-6);
}

TEST(Head, PitchRangeTightensAtLargeYaw) {
  float lo0, hi0, lo1, hi1;
  headPitchRange(0.0f, &lo0, &hi0);
  headPitchRange(2.0f, &lo1, &hi1);
  EXPECT_LT(lo0, lo1);
  EXPECT_GT(hi0, hi1);
}

TEST(Kick, RunsToCompletionWithinLimitsAndLiftsTheKickingFoot) {
  WalkConfig wc;
  for (auto foot : {bb::Foot::LEFT, bb::Foot::RIGHT}) {
    KickGenerator kick(wc);
    kick.start(foot, 1.0, 0.2);
    common::libagent::SensorValues s{};
    common::libagent::JointValues out{};
    double max_knee_diff = 0;
    int ticks = 0;
    while (!kick.done() && ticks < 1000) {
      kick.tick(s, 0.01, out);
      const double d = out.angles[foot == bb::Foot::RIGHT ? J::RKneePitch : J::LKneePitch] -
                       out.angles[foot == bb::Foot::RIGHT ? J::LKneePitch : J::RKneePitch];
      max_knee_diff = std::max(max_knee_diff, d);
      ++ticks;
    }
    EXPECT_TRUE(kick.done());
    EXPECT_LT(ticks, 400);
    EXPECT_GT(max_knee_diff, 0.3);  // the kicking knee bends to lift the foot
  }
}

// The strike's reaction turns the robot about the stance foot; the arms swing
// against the kicking leg (kicking side back, the other forward) to take part
// of it. And the kick asks no joint (hands aside: closed is their end) for an
// angle at or past its range's end: a level kicking sole with the hips over
// the support foot would need more AnkleRoll than the joint has.
TEST(Kick, ArmsSwingAgainstTheLegAndNoJointIsSentToItsStop) {
  WalkConfig wc;
  const auto& lim = agent::motion::jointLimits();
  for (auto foot : {bb::Foot::LEFT, bb::Foot::RIGHT}) {
    const bool right = foot == bb::Foot::RIGHT;
    KickGenerator kick(wc);
    kick.start(foot, 1.0, 0.0);
    common::libagent::SensorValues s{};
    common::libagent::JointValues out{};
    // rad: the kicking HipPitch's extremes (< 0 is the thigh forward: the
    // strike; the largest is the wind-back) and, there, the kicking side's
    // ShoulderPitch minus the other's (> 0: the kicking side's arm further back).
    double strike_hip = 1e9, windback_hip = -1e9;
    double arm_at_strike = 0, arm_at_windback = 0;
    double closest = 1e9;                     // rad, nearest any command came to its range's ends
    for (int ticks = 0; !kick.done() && ticks < 1000; ++ticks) {
      kick.tick(s, 0.01, out);
      const double hip = out.angles[right ? J::RHipPitch : J::LHipPitch];
      const double arm = out.angles[right ? J::RShoulderPitch : J::LShoulderPitch] -
                         out.angles[right ? J::LShoulderPitch : J::RShoulderPitch];
      if (hip < strike_hip) { strike_hip = hip; arm_at_strike = arm; }
      if (hip > windback_hip) { windback_hip = hip; arm_at_windback = arm; }
      for (int j = 0; j < common::libagent::kNumJoints; ++j) {
        if (j == J::LHand || j == J::RHand) continue;
        const double room = std::min(out.angles[j] - lim[j].lower, lim[j].upper - out.angles[j]);
        closest = std::min(closest, room);
      }
    }
    EXPECT_GT(arm_at_strike, 1.0) << (right ? "right" : "left");      // kicking-side arm back at the strike
    EXPECT_LT(arm_at_windback, -0.5) << (right ? "right" : "left");  // and forward at the wind-back
    // The support HipRoll comes closest (0.017 rad, with the hips 70 mm over).
    EXPECT_GE(closest, 0.01) << (right ? "right" : "left");
  }
}

TEST(ActionMotion, WalksPublishesOdometryAndStaysWithinLimits) {
  ActionMotion motion;
  bb::MotionRequest req;
  req.body.type = bb::ActionType::WALK;
  req.body.forward = 250;
  req.sequence = 1;
  motion.setRequest(req);
  common::libagent::JointValues cmd{};
  common::libagent::SensorValues s = standingSensors(cmd);
  float prev[common::libagent::kNumJoints];
  for (int t = 0; t < 500; ++t) {
    motion.tickSeconds(s, t * 0.01, cmd);
    expectWithinLimits(cmd, t > 0 ? prev : nullptr);
    for (int i = 0; i < common::libagent::kNumJoints; ++i) prev[i] = cmd.angles[i];
    // A perfect body: sensed angles follow the commands, and the weight is
    // on the support foot until the swing foot is down (80 % of the step).
    s.joints = cmd;
    const auto& w = motion.walk();
    const bool landed = w.stepping() && w.stepTime() > 0.8 * w.stepPeriod();
    const bool on_left = w.leftIsSwing() ? landed : !landed;
    for (int i = 0; i < 4; ++i) {
      s.sensors[S::LFoot_FSR_FrontLeft + i] = on_left ? 1.0f : 0.05f;  // kg
      s.sensors[S::RFoot_FSR_FrontLeft + i] = on_left ? 0.05f : 1.0f;
    }
  }
  const bb::MotionState st = motion.state();
  EXPECT_EQ(st.posture, bb::BodyState::WALKING);
  EXPECT_TRUE(st.walk_stepping);
  EXPECT_GT(st.odometry.forward, 500);  // mm over ~4.5 s of stepping
  EXPECT_NEAR(st.odometry.x, st.odometry.forward, 1e-6);
  EXPECT_EQ(st.tick, 500);
}

TEST(ActionMotion, FallGoesLimpThenGetsUpFromTheRightSide) {
  ActionMotion motion;
  bb::MotionRequest req;
  req.body.type = bb::ActionType::STAND;
  motion.setRequest(req);
  common::libagent::JointValues cmd{};
  common::libagent::SensorValues s = standingSensors(cmd);
  for (int t = 0; t < 50; ++t) motion.tickSeconds(s, t * 0.01, cmd);
  // Tip forward past the fall angle: limp at once.
  s.sensors[S::InertialSensor_AngleY] = 0.9f;
  s.sensors[S::InertialSensor_GyrY] = 3.0f;
  motion.tickSeconds(s, 0.5, cmd);
  EXPECT_EQ(motion.mode(), ActionMotion::Mode::Falling);
  EXPECT_EQ(motion.state().posture, bb::BodyState::FALLING);
  for (int i = 0; i < common::libagent::kNumJoints; ++i) EXPECT_LE(cmd.stiffnesses[i], 0.0f);
  // Lying face down and still: the front get-up starts.
  s.sensors[S::InertialSensor_AngleY] = 1.5f;
  s.sensors[S::InertialSensor_GyrY] = 0.0f;
  double t = 0.51;
  for (int i = 0; i < 40; ++i, t += 0.01) motion.tickSeconds(s, t, cmd);
  EXPECT_EQ(motion.mode(), ActionMotion::Mode::Getup);
  EXPECT_EQ(motion.state().active, bb::ActionType::GETUP_FRONT);
  // Pretend it worked: upright again at the end of the sequence.
  s.sensors[S::InertialSensor_AngleY] = 0.0f;
  for (int i = 0; i < 800 && motion.mode() == ActionMotion::Mode::Getup; ++i, t += 0.01)
    motion.tickSeconds(s, t, cmd);
  EXPECT_EQ(motion.mode(), ActionMotion::Mode::Walk);
  EXPECT_EQ(motion.state().posture, bb::BodyState::STANDING);
  EXPECT_EQ(motion.getupAttempts(), 1);
}

TEST(ActionMotion, BackFallChoosesBackGetupAndDeadIsLimp) {
  ActionMotion motion;
  common::libagent::JointValues cmd{};
  common::libagent::SensorValues s = standingSensors(cmd);
  s.sensors[S::InertialSensor_AngleY] = -1.5f;
  double t = 0;
  for (int i = 0; i < 60; ++i, t += 0.01) motion.tickSeconds(s, t, cmd);
  EXPECT_EQ(motion.state().active, bb::ActionType::GETUP_BACK);
  bb::MotionRequest req;
  req.body.type = bb::ActionType::DEAD;
  motion.setRequest(req);
  motion.tickSeconds(s, t, cmd);
  for (int i = 0; i < common::libagent::kNumJoints; ++i) EXPECT_EQ(cmd.stiffnesses[i], -1.0f);
}

TEST(ActionMotion, KickRequestRunsTheKickOnce) {
  ActionMotion motion;
  bb::MotionRequest req;
  req.body.type = bb::ActionType::KICK;
  req.body.foot = bb::Foot::LEFT;
  req.sequence = 7;
  motion.setRequest(req);
  common::libagent::JointValues cmd{};
  common::libagent::SensorValues s = standingSensors(cmd);
  bool kicked = false;
  double t = 0;
  for (int i = 0; i < 600; ++i, t += 0.01) {
    motion.tickSeconds(s, t, cmd);
    s.joints = cmd;
    if (motion.mode() == ActionMotion::Mode::Kick) {
      kicked = true;
      EXPECT_EQ(motion.state().support_foot, bb::Foot::RIGHT);
    }
  }
  EXPECT_TRUE(kicked);
  EXPECT_EQ(motion.mode(), ActionMotion::Mode::Walk);  // once, not repeated
}

// lifted_weight is compared with the FSRs' sum in kg (their unit): a robot
// walking on its 5.3 kg keeps stepping; one whose feet carry 2.4 kg (picked
// up by the torso) for more than 0.5 s is asked to stop.
TEST(ActionMotion, PickedUpInKgStopsWalkingFullWeightDoesNot) {
  for (const float per_sensor : {0.66f, 0.3f}) {  // kg each of 8: 5.3 kg, 2.4 kg
    ActionMotion motion;
    bb::MotionRequest req;
    req.body.type = bb::ActionType::WALK;
    req.body.forward = 200;
    req.sequence = 1;
    motion.setRequest(req);
    common::libagent::JointValues cmd{};
    common::libagent::SensorValues s = standingSensors(cmd);
    bool stepped = false;
    for (int t = 0; t < 300; ++t) {
      motion.tickSeconds(s, t * 0.01, cmd);
      s.joints = cmd;
      stepped = stepped || motion.walk().stepping();
      if (t == 100)  // 1 s of walking on full weight, then the weight of this case
        for (int i = 0; i < 4; ++i) s.sensors[S::LFoot_FSR_FrontLeft + i] = s.sensors[S::RFoot_FSR_FrontLeft + i] = per_sensor;
    }
    EXPECT_LT(MotionConfig{}.lifted_weight, 8 * 0.66);  // kg: below a standing NAO's
    EXPECT_TRUE(stepped);
    // This step's forward speed (mm/s): the request's on full weight; none
    // once picked up (the walk is asked to stop).
    if (per_sensor > 0.5f) EXPECT_GT(motion.walk().latched().forward, 100) << "full weight: still walking";
    else EXPECT_NEAR(motion.walk().latched().forward, 0, 1e-6) << "2.4 kg for 2 s: picked up, stops";
  }
}
