// ServoBank: the DCM-like servo law, clamps and invalid-command handling.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sim/nao_model/Servo.hpp"

using simswift::ServoBank;
using simswift::ServoConfig;

namespace {
ServoBank bank() {
  ServoConfig cfg;
  cfg.kp = 50;
  cfg.torque_scale = 1.0;
  cfg.limp_damping = 0.02;
  // One joint: -1..1 rad, 4 rad/s, 10 N*m.
  return ServoBank({{-1.0, 1.0, 4.0, 10.0}}, cfg);
}
}  // namespace

TEST(Servo, SpeedLimitAndProportionalLaw) {
  ServoBank s = bank();
  s.setTarget(0, 0.9, 1.0);
  const auto far = s.drive(0, -0.9, 0.005);     // 1.8 rad error: kp*e = 90 rad/s
  EXPECT_DOUBLE_EQ(far.velocity, 4.0);          // clamped to max speed
  EXPECT_DOUBLE_EQ(far.max_torque, 10.0);       // stiffness 1 * effort
  const auto near = s.drive(0, 0.88, 0.005);    // 0.02 rad: kp*e = 1 rad/s
  EXPECT_NEAR(near.velocity, 1.0, 1e-12);
  const auto back = s.drive(0, 1.0, 0.005);
  EXPECT_DOUBLE_EQ(back.velocity, -4.0);  // -0.1 rad * 50 = -5, clamped
}

TEST(Servo, NeverOvershootsWithinOneStep) {
  ServoConfig cfg;
  cfg.kp = 1000;  // would jump past the target in a 10 ms step
  ServoBank s({{-1.0, 1.0, 8.0, 10.0}}, cfg);
  s.setTarget(0, 0.5, 1.0);
  const auto d = s.drive(0, 0.49, 0.010);
  EXPECT_NEAR(d.velocity, 0.01 / 0.010, 1e-12);  // exactly reaches the target
}

TEST(Servo, StiffnessScalesTorqueAndLimpIsWeak) {
  ServoBank s = bank();
  s.setTarget(0, 0.5, 0.3);
  EXPECT_NEAR(s.drive(0, 0.0, 0.005).max_torque, 3.0, 1e-12);
  s.setTarget(0, 0.5, -1.0);  // off
  const auto limp = s.drive(0, 0.0, 0.005);
  EXPECT_EQ(limp.velocity, 0.0);
  EXPECT_NEAR(limp.max_torque, 0.02 * 4.0, 1e-12);
  s.setTarget(0, 0.5, 0.0);
  EXPECT_NEAR(s.drive(0, 0.0, 0.005).max_torque, 0.08, 1e-12);
}

TEST(Servo, ClampsAreCounted) {
  ServoBank s = bank();
  s.setTarget(0, 2.5, 1.0);
  EXPECT_DOUBLE_EQ(s.target(0), 1.0);
  s.setTarget(0, -3.0, 1.7);
  EXPECT_DOUBLE_EQ(s.target(0), -1.0);
  EXPECT_DOUBLE_EQ(s.stiffness(0), 1.0);
  s.setTarget(0, 0.2, -4.0);
  EXPECT_DOUBLE_EQ(s.stiffness(0), -1.0);
  s.setTarget(0, 0.2, 0.5);  // valid: not counted
  EXPECT_EQ(s.stats().clamped_angles, 2);
  EXPECT_EQ(s.stats().clamped_stiffness, 2);
  EXPECT_EQ(s.stats().nan_commands, 0);
}

TEST(Servo, NanAndInfAreHeldAtLastGoodValue) {
  ServoBank s = bank();
  s.setTarget(0, 0.4, 0.8);
  s.setTarget(0, std::numeric_limits<double>::quiet_NaN(), 0.6);
  EXPECT_DOUBLE_EQ(s.target(0), 0.4);
  EXPECT_DOUBLE_EQ(s.stiffness(0), 0.6);
  s.setTarget(0, 0.1, std::numeric_limits<double>::infinity());
  EXPECT_DOUBLE_EQ(s.target(0), 0.1);
  EXPECT_DOUBLE_EQ(s.stiffness(0), 0.6);
  EXPECT_EQ(s.stats().nan_commands, 2);
  EXPECT_EQ(s.stats().clamped_stiffness, 0);
  const auto d = s.drive(0, 0.0, 0.005);
  EXPECT_TRUE(std::isfinite(d.velocity));
}

TEST(Servo, FollowCopiesLeader) {
  ServoBank s({{-1, 1, 4, 10}, {-1, 1, 4, 10}});
  s.setTarget(0, 0.7, 0.9);
  s.follow(1, 0, 1.0);
  EXPECT_DOUBLE_EQ(s.target(1), 0.7);
  EXPECT_DOUBLE_EQ(s.stiffness(1), 0.9);
  EXPECT_EQ(s.stats().clamped_angles, 0);
}
