// ServoBank: the DCM-like servo law, clamps and invalid-command handling.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include <ode/ode.h>

#include "sim/nao_model/Motors.hpp"
#include "sim/nao_model/Servo.hpp"

using simswift::ServoBank;
using simswift::ServoConfig;

namespace {
ServoBank bank() {
  ServoConfig cfg;
  cfg.kp = 50;
  cfg.torque_scale = 1.0;
  cfg.limp_damping = 0.02;
  cfg.gear_efficiency = 1.0;  // torques below are then the stall torque
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

// The motor's torque-speed line as the drive states it: compliance = no-load
// speed / (efficiency x stall), the cap = stiffness x efficiency x stall.
TEST(Servo, TorqueSpeedLineAndCurrentLimit) {
  ServoConfig cfg;
  cfg.gear_efficiency = 0.8;
  cfg.torque_speed_line = true;
  ServoBank s({{-2.0, 2.0, 4.0, 10.0}}, cfg);  // no-load 4 rad/s, stall 10 N*m
  s.setTarget(0, 1.0, 1.0);
  const auto d = s.drive(0, 0.0, 0.005);
  EXPECT_NEAR(d.max_torque, 8.0, 1e-12);      // 0.8 x 10
  EXPECT_NEAR(d.compliance, 4.0 / 8.0, 1e-12);
  // torque = (velocity - w) / compliance: stall at rest, 0 at no-load.
  EXPECT_NEAR((d.velocity - 0.0) / d.compliance, 8.0, 1e-12);
  EXPECT_NEAR((d.velocity - 3.0) / d.compliance, 2.0, 1e-12);
  s.setTarget(0, 1.0, 0.5);  // stiffness scales the current limit only
  EXPECT_NEAR(s.drive(0, 0.0, 0.005).max_torque, 4.0, 1e-12);
  EXPECT_NEAR(s.drive(0, 0.0, 0.005).compliance, 0.5, 1e-12);
}

// Current from torque through reduction, efficiency and k_t; the winding
// settles at ambient + I^2 R R_th; the DCM's limit falls when hot.
TEST(Servo, CurrentHeatsAndHotMotorsAreDerated) {
  ServoConfig cfg;
  cfg.gear_efficiency = 0.5;
  ServoBank::Limits lim{-1.0, 1.0, 4.0, 10.0};
  lim.reduction = 100;
  lim.torque_constant = 0.01;  // N*m/A
  lim.resistance = 2.0;        // ohm
  ServoBank s({lim}, cfg);
  s.setTarget(0, 0.0, 1.0);
  s.heat(0, -1.0, 0.01);  // 1 N*m at the joint = 0.02 N*m at the motor = 2 A
  EXPECT_NEAR(s.current(0), 2.0, 1e-12);
  EXPECT_LT(s.temperature(0) - cfg.ambient_temperature, 0.01);  // invisible per tick
  for (int i = 0; i < 3000; ++i) s.heat(0, 1.0, 1.0);  // 3000 s at 2 A: 8 W
  EXPECT_NEAR(s.temperature(0), cfg.ambient_temperature + 8.0 * cfg.thermal_resistance, 0.1);
  EXPECT_NEAR(s.thermalLimit(0), cfg.hot_min_fraction, 1e-12);  // 187 deg C: fully derated
  EXPECT_NEAR(s.drive(0, -0.5, 0.005).max_torque, cfg.hot_min_fraction * 5.0, 1e-12);
  s.setTemperature(0, 0.5 * (cfg.hot_start + cfg.hot_end));
  EXPECT_NEAR(s.thermalLimit(0), 0.5 * (1.0 + cfg.hot_min_fraction), 1e-12);
  for (int i = 0; i < 3000; ++i) s.heat(0, 0.0, 1.0);  // unloaded: cools back
  EXPECT_NEAR(s.temperature(0), cfg.ambient_temperature, 0.1);
  EXPECT_DOUBLE_EQ(s.thermalLimit(0), 1.0);
}

// In physics: a knee motor (RE-Max 24, type B) turns a flywheel on an ODE
// hinge against a constant load torque. It settles where the torque-speed
// line meets the load: speed = no-load x (1 - load / (efficiency x stall)).
TEST(Servo, JointUnderKnownLoadSlowsAlongTheTorqueSpeedLine) {
  const simswift::JointMotor knee = *simswift::naoJointMotor("LKneePitch");
  ServoConfig cfg;
  cfg.torque_speed_line = true;
  cfg.gear_efficiency = 0.8;
  const double stall = cfg.gear_efficiency * knee.stallTorque();  // N*m at the joint
  for (double fraction : {0.0, 0.25, 0.5, 0.75}) {
    dInitODE2(0);
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetSphereTotal(&m, 1.0, 0.05);  // 1e-3 kg m^2 flywheel, no gravity
    dBodySetMass(b, &m);
    dJointID h = dJointCreateHinge(w, nullptr);
    dJointAttach(h, b, nullptr);
    dJointSetHingeAnchor(h, 0, 0, 0);
    dJointSetHingeAxis(h, 0, 0, 1);
    ServoBank s({{-1e9, 1e9, knee.noLoadSpeed(), knee.stallTorque()}}, cfg);
    s.setTarget(0, 1e6, 1.0);  // far ahead: full speed wanted
    const double load = fraction * stall;
    const double dt = 0.005;
    for (int i = 0; i < 400; ++i) {  // 2 s
      const auto d = s.drive(0, dJointGetHingeAngle(h), dt);
      dJointSetHingeParam(h, dParamVel, d.velocity);
      dJointSetHingeParam(h, dParamFMax, d.max_torque);
      dJointSetHingeParam(h, dParamCFM, d.compliance);
      dBodyAddTorque(b, 0, 0, -load);
      dWorldStep(w, dt);
    }
    const double speed = dJointGetHingeAngleRate(h);
    const double expected = knee.noLoadSpeed() * (1.0 - fraction);
    std::printf("[servo] knee motor, load %.0f %% of stall: %.2f rad/s (line: %.2f)\n", fraction * 100, speed,
                expected);
    EXPECT_NEAR(speed, expected, 0.03 * knee.noLoadSpeed()) << "load fraction " << fraction;
    dWorldDestroy(w);
  }
}

// The defaults are the NAO's motor: the torque-speed line on,
// gear efficiency 0.8, a 10 ms position loop.
TEST(Servo, DefaultsAreTheFaithfulMotor) {
  const ServoConfig cfg;
  EXPECT_TRUE(cfg.torque_speed_line);
  EXPECT_DOUBLE_EQ(cfg.gear_efficiency, 0.8);
  EXPECT_DOUBLE_EQ(cfg.kp, 100.0);
}
