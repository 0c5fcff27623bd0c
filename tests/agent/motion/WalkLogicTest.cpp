// Pure-logic tests of the walk: the ellipsoid clamp, the per-step ratchet,
// support-foot switching with synthetic FSRs, and odometry integration.
// Units: mm, mm/s, rad, rad/s, s, N.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "agent/motion/Walk2014Generator.hpp"

using namespace agent::motion;
namespace S = common::libagent::Sensors;

namespace {

double ellipsoid(const WalkSpeed& w, const WalkConfig& c) {
  return std::pow(w.forward / c.max_forward, 2) + std::pow(w.left / c.max_left, 2) +
         std::pow(w.turn / c.max_turn, 2);
}

// Sensors with `left_n` / `right_n` newtons spread evenly over each foot's
// FSRs, in the NAO's unit (kg).
common::libagent::SensorValues withWeight(double left_n, double right_n) {
  common::libagent::SensorValues s{};
  const double g = common::libagent::kFsrNewtonsPerKilogram;
  for (int i = 0; i < 4; ++i) {
    s.sensors[S::LFoot_FSR_FrontLeft + i] = static_cast<float>(left_n / g / 4);
    s.sensors[S::RFoot_FSR_FrontLeft + i] = static_cast<float>(right_n / g / 4);
  }
  return s;
}

// The walk's geometry alone: calibration gains and scales at 1, no heading
// hold, odometry turn from the feet.
WalkConfig geometryConfig() {
  WalkConfig c;
  c.forward_gains = c.left_gains = {1.0, 1.0, 1.0, 1.0};
  c.turn_gain = 1.0;
  c.odometry_forward_scale = c.odometry_left_scale = c.odometry_turn_scale = 1.0;
  c.heading_gain = 0.0;
  c.odometry_turn_from_gyro = false;
  return c;
}

}  // namespace

TEST(WalkClamp, InsideLimitsUnchanged) {
  WalkConfig c;
  const WalkSpeed w = ellipsoidClamp({100, 50, 0.2}, c);
  EXPECT_DOUBLE_EQ(w.forward, 100);
  EXPECT_DOUBLE_EQ(w.left, 50);
  EXPECT_DOUBLE_EQ(w.turn, 0.2);
}

TEST(WalkClamp, SingleAxesClampToTheirLimits) {
  WalkConfig c;
  EXPECT_NEAR(ellipsoidClamp({1000, 0, 0}, c).forward, 300, 1e-9);
  EXPECT_NEAR(ellipsoidClamp({0, -900, 0}, c).left, -200, 1e-9);
  EXPECT_NEAR(ellipsoidClamp({0, 0, 5}, c).turn, 0.8, 1e-9);
}

TEST(WalkClamp, CombinedStaysOnEllipsoidAndTurnHasPriority) {
  WalkConfig c;
  for (double f = -600; f <= 600; f += 150)
    for (double l = -400; l <= 400; l += 100)
      for (double t = -1.6; t <= 1.61; t += 0.4) {
        const WalkSpeed w = ellipsoidClamp({f, l, t}, c);
        EXPECT_LE(ellipsoid(w, c), 1.0 + 1e-9);
        // Turn is only ever cut by its own limit.
        EXPECT_NEAR(w.turn, std::max(-0.8, std::min(0.8, t)), 1e-9);
        // Direction of (forward, left) is kept.
        if (f != 0 && w.forward != 0) {
          EXPECT_NEAR(w.left / w.forward, l / f, 1e-9);
        }
      }
  // Full turn leaves nothing for translation.
  const WalkSpeed w = ellipsoidClamp({300, 0, 0.8}, c);
  EXPECT_NEAR(w.forward, 0, 1e-9);
}

TEST(WalkRatchet, LimitsChangePerStep) {
  WalkConfig c;
  WalkSpeed cur{};
  const WalkSpeed target{300, -200, 0.8};
  int steps = 0;
  while ((cur.forward != target.forward || cur.left != target.left || cur.turn != target.turn) && steps < 100) {
    const WalkSpeed next = ratchet(cur, target, c);
    EXPECT_LE(std::fabs(next.forward - cur.forward), c.ratchet_forward + 1e-9);
    EXPECT_LE(std::fabs(next.left - cur.left), c.ratchet_left + 1e-9);
    EXPECT_LE(std::fabs(next.turn - cur.turn), c.ratchet_turn + 1e-9);
    cur = next;
    ++steps;
  }
  EXPECT_EQ(steps, 5);  // 300 / 60 forward dominates
  EXPECT_DOUBLE_EQ(cur.forward, 300);
}

TEST(WalkSupportSwitch, CopSignChangeAfterThreeQuartersOfThePeriod) {
  WalkConfig c;
  SupportSwitch sw(c);
  const double T = 0.25;
  const FootPressure on_left = footPressure(withWeight(40, 2).sensors);
  const FootPressure on_right = footPressure(withWeight(2, 40).sensors);
  EXPECT_GT(on_left.cop_y, 0);
  EXPECT_LT(on_right.cop_y, 0);
  // Swinging the left foot: weight on the right until it lands.
  EXPECT_FALSE(sw.shouldSwitch(0.1, T, true, on_right));
  EXPECT_FALSE(sw.shouldSwitch(0.1, T, true, on_left));   // too early (< 0.75 T)
  EXPECT_TRUE(sw.shouldSwitch(0.19, T, true, on_left));   // after 0.75 T, CoP crossed
  EXPECT_FALSE(sw.shouldSwitch(0.5, T, true, on_right));  // still on support, not yet forced
  EXPECT_TRUE(sw.shouldSwitch(0.75, T, true, on_right));  // forced at 3 T
  // Mirror for the right swing foot.
  EXPECT_TRUE(sw.shouldSwitch(0.19, T, false, on_right));
  EXPECT_FALSE(sw.shouldSwitch(0.19, T, false, on_left));
  // No weight (lifted): switch on time.
  const FootPressure air = footPressure(withWeight(0, 0).sensors);
  EXPECT_FALSE(sw.shouldSwitch(0.2, T, true, air));
  EXPECT_TRUE(sw.shouldSwitch(0.25, T, true, air));
}

// Drives the generator with FSRs that follow the gait (the weight on the
// support foot, moving to the swing foot once it is down).
TEST(WalkGenerator, FeetAlternateWithSyntheticFsrsAndOdometryIntegrates) {
  const WalkConfig c = geometryConfig();
  Walk2014Generator walk(c);
  walk.setRequest(true, {200, 0, 0});
  common::libagent::JointValues out{};
  double forward = 0, left = 0, turn = 0;
  int switches = 0;
  bool last_swing = walk.leftIsSwing();
  const double dt = 0.01;
  for (int i = 0; i < 600; ++i) {
    // Weight on the support foot until 80 % of the step, then on the swing foot.
    const bool landed = walk.stepping() && walk.stepTime() > 0.8 * walk.stepPeriod();
    const bool weight_left = walk.leftIsSwing() ? landed : !landed;
    const auto s = weight_left ? withWeight(40, 2) : withWeight(2, 40);
    walk.tick(s, dt, out);
    forward += walk.lastOdometry().forward;
    left += walk.lastOdometry().left;
    turn += walk.lastOdometry().turn;
    if (walk.stepping() && walk.leftIsSwing() != last_swing) {
      ++switches;
      last_swing = walk.leftIsSwing();
    }
    for (int j = 0; j < common::libagent::kNumJoints; ++j) ASSERT_TRUE(std::isfinite(out.angles[j]));
  }
  // 6 s: 0.5 s sinking, then steps of ~0.2 s (switch at 0.8 T with T = 0.25 s).
  EXPECT_GT(switches, 20);
  EXPECT_LT(switches, 30);
  EXPECT_EQ(walk.latched().forward, 200);
  // Each step advances forward * T while stepping at 0.8 T: odometry counts
  // what the feet did, so it is between 0.8 and 1.0 of 200 mm/s * stepping time.
  EXPECT_GT(forward, 0.8 * 0.8 * 200 * 5.5);
  // Feet finish their horizontal travel by horizontal_fraction of the step,
  // or by when the last step on that side ended (here 0.8 T), so each step
  // switched at 0.8 T covers at most its whole length in 0.8 T.
  EXPECT_LT(forward, 200 * 5.5 / 0.8);
  EXPECT_NEAR(left, 0, 1.0);
  EXPECT_NEAR(turn, 0, 1e-6);
}

TEST(WalkGenerator, StopsThroughAStandAndRisesToStandHeight) {
  const WalkConfig c = geometryConfig();
  Walk2014Generator walk(c);
  common::libagent::JointValues out{};
  const auto air = withWeight(0, 0);
  walk.setRequest(true, {300, 0, 0.5});
  for (int i = 0; i < 300; ++i) walk.tick(air, 0.01, out);
  EXPECT_TRUE(walk.stepping());
  walk.setRequest(false, {});
  int ticks = 0;
  while (!walk.standing() && ticks < 1000) {
    walk.tick(air, 0.01, out);
    ++ticks;
  }
  EXPECT_TRUE(walk.standing());
  EXPECT_LT(ticks, 600);  // ratchet down (<= 5 steps) + settle step + rise
  EXPECT_NEAR(walk.feet().zl, -c.stand_hip_height, 1e-9);
  EXPECT_NEAR(walk.feet().xl, 0, 1e-9);
  EXPECT_NEAR(walk.feet().th, 0, 1e-9);
}

TEST(WalkGenerator, TurnAndSideOdometryHaveTheRightSigns) {
  const WalkConfig c = geometryConfig();
  const auto air = withWeight(0, 0);
  common::libagent::JointValues out{};
  {
    Walk2014Generator walk(c);
    walk.setRequest(true, {0, 0, 0.6});
    double turn = 0;
    for (int i = 0; i < 400; ++i) {
      walk.tick(air, 0.01, out);
      turn += walk.lastOdometry().turn;
    }
    // 3.5 s of stepping at up to 0.6 rad/s (ratchet: 0.25, 0.5, 0.6...).
    EXPECT_GT(turn, 0.6 * 3.5 * 0.8);
    EXPECT_LT(turn, 0.6 * 3.5 * 1.05);
  }
  {
    Walk2014Generator walk(c);
    walk.setRequest(true, {0, -150, 0});
    double left = 0;
    for (int i = 0; i < 400; ++i) {
      walk.tick(air, 0.01, out);
      left += walk.lastOdometry().left;
    }
    EXPECT_LT(left, -150 * 3.5 * 0.7);
    EXPECT_GT(left, -150 * 3.5 * 1.05);
  }
}

// The forward gain comes from the table at the commanded fraction of
// max_forward; odometry reports the commanded (pre-gain) motion.
TEST(WalkGenerator, GainTableScalesTheStepAndOdometryReportsTheCommand) {
  WalkConfig c = geometryConfig();
  c.forward_gains = {1.0, 1.5, 2.0, 2.0};  // 150 mm/s = 50 % of 300 -> gain 1.5
  Walk2014Generator walk(c);
  walk.setRequest(true, {150, 0, 0});
  common::libagent::JointValues out{};
  const auto air = withWeight(0, 0);
  for (int i = 0; i < 300; ++i) walk.tick(air, 0.01, out);  // ramp up to 150
  ASSERT_EQ(walk.latched().forward, 150);
  double max_x = 0, forward = 0;
  for (int i = 0; i < 200; ++i) {
    walk.tick(air, 0.01, out);
    max_x = std::max({max_x, walk.feet().xl, walk.feet().xr});
    forward += walk.lastOdometry().forward;
  }
  // The swing foot lands F / 2 ahead of the hips, F = gain * speed * T (mm).
  EXPECT_NEAR(max_x, 1.5 * 150 * c.period / 2, 0.5);
  // 2 s at 150 mm/s, stepping all the time in the air: 300 mm within 5 %.
  EXPECT_NEAR(forward, 300, 15);
}
