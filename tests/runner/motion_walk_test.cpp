// Motion in physics: the ActionMotion drives the simulated NAO
// through the libagent block only; the test plays Behaviour through the
// Blackboard. Seeded, noise on. Achieved figures are printed.
// Units: m / rad in the field frame, mm/s and rad/s for commands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "app/api/WalkSampling.hpp"
#include "simswift/WalkTest.hpp"
#include "harness/MotionHarness.hpp"

using agent::blackboard::ActionType;
using motion_test::MotionHarness;
using motion_test::Pose2;
using motion_test::wrapAngle;

namespace {

// Displacement from a to b in a's heading frame (m): forward, left (the
// odometry checks; the walk's achieved figures come from the kit's meter).
void relative(const Pose2& a, const Pose2& b, double* fwd, double* left) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  const double dx = b.x - a.x, dy = b.y - a.y;
  *fwd = c * dx + s * dy;
  *left = -s * dx + c * dy;
}

// Walks at the command (mm/s, rad/s) for 2 s to reach speed, then `seconds`
// more, measured by the walk test kit's meter (include/simswift/WalkTest.hpp:
// achieved mm/s and rad/s in the heading frame at the window's start, heading
// slope, stance slip). *ok: false if the robot fell.
simswift::WalkFigures walkMeasured(MotionHarness& h, double forward, double left, double turn, double seconds,
                                   bool* ok) {
  h.request(ActionType::WALK, forward, left, turn);
  *ok = h.run(2.0);
  simswift::WalkMeter meter;
  meter.begin(simswift::api::walkSample(h.runner(), 0), {forward, left, turn});
  for (long i = 0; i < std::lround(seconds / 0.01); ++i) {
    *ok = h.run(0.01) && *ok;
    meter.add(simswift::api::walkSample(h.runner(), 0));
  }
  return meter.figures();
}

}  // namespace

TEST(MotionPhysics, StandsStill) {
  MotionHarness h(1);
  h.request(ActionType::STAND);
  EXPECT_TRUE(h.run(3.0));
  const auto p = h.pose();
  EXPECT_NEAR(p.x, -3.0, 0.03);
  EXPECT_NEAR(p.y, 0.0, 0.03);
}

// Walk forward at 300 mm/s for 20 s: no fall, >= 90 % of the speed, sideways
// drift <= 10 % of the distance. Measured over the 20 s after a 2 s start.
TEST(MotionPhysics, WalkForwardFullSpeed) {
  MotionHarness h(11, -4.0, 0.0, 0.0);
  h.request(ActionType::STAND);
  ASSERT_TRUE(h.run(1.0));
  bool ok;
  const simswift::WalkFigures f = walkMeasured(h, 300, 0, 0, 20.0, &ok);
  std::printf("[motion] forward 300 mm/s x 20 s: %.0f mm/s (%.0f %%), drift %.0f mm (%.0f %% of distance)\n",
              f.forward, f.forward_ratio * 100, f.left * 20, std::fabs(f.left / f.forward) * 100);
  EXPECT_TRUE(ok) << "fell";
  EXPECT_GE(f.forward_ratio, 0.9) << f.summary();
  EXPECT_LE(std::fabs(f.left), 0.1 * std::fabs(f.forward)) << f.summary();
  EXPECT_EQ(h.checked().limit_violations, 0);
  EXPECT_EQ(h.checked().speed_violations, 0);
}

// Side-step at 200 mm/s and turn in place at 0.8 rad/s: >= 80 %, no fall.
TEST(MotionPhysics, SideStepFullSpeed) {
  MotionHarness h(12);
  h.request(ActionType::STAND);
  ASSERT_TRUE(h.run(1.0));
  bool ok;
  const simswift::WalkFigures f = walkMeasured(h, 0, 200, 0, 8.0, &ok);
  std::printf("[motion] left 200 mm/s x 8 s: %.0f mm/s (%.0f %%), forward drift %.0f mm\n", f.left,
              f.left_ratio * 100, f.forward * 8);
  EXPECT_TRUE(ok) << "fell";
  EXPECT_GE(f.left_ratio, 0.85) << f.summary();
}

// The turn's odometry too: the program's (gyro heading rate while stepping)
// and an unchanged rUNSWift 2017/2018 MotionOdometry's gyro turn, -0.01 x
// GyroscopeZ per 10 ms frame (before its 0.95 pessimism), read from the slots
// the body published: both must turn the way the robot turns (the V5's
// GyroscopeZ is negative for an anti-clockwise turn; common/libagent/Inertial.hpp).
TEST(MotionPhysics, TurnInPlaceFullSpeed) {
  MotionHarness h(13);
  h.request(ActionType::STAND);
  ASSERT_TRUE(h.run(1.0));
  h.request(ActionType::WALK, 0, 0, 0.8);
  bool ok = h.run(2.0);
  simswift::WalkMeter meter;
  meter.begin(simswift::api::walkSample(h.runner(), 0), {0, 0, 0.8});
  double turned = 0, last = h.pose().theta;
  double odometry = 0, odometry_last = h.state().odometry.theta, runswift = 0;  // rad
  for (int i = 0; i < 800; ++i) {
    ok = h.run(0.01) && ok;
    meter.add(simswift::api::walkSample(h.runner(), 0));
    const double th = h.pose().theta;
    turned += wrapAngle(th - last);
    last = th;
    odometry += wrapAngle(h.state().odometry.theta - odometry_last);
    odometry_last = h.state().odometry.theta;
    runswift += -0.01 * h.checked().last_sensed.sensors[common::libagent::Sensors::InertialSensor_GyroscopeZ];
  }
  const simswift::WalkFigures f = meter.figures();
  std::printf("[motion] turn 0.8 rad/s x 8 s: %.3f rad/s (%.0f %%); odometry %.3f of it, rUNSWift's gyro "
              "odometry %.3f of it\n",
              f.turn, f.turn_ratio * 100, odometry / turned, runswift / turned);
  EXPECT_TRUE(ok) << "fell";
  EXPECT_GE(f.turn_ratio, 0.85) << f.summary();
  EXPECT_NEAR(odometry / turned, 1.0, 0.03);
  EXPECT_NEAR(runswift / turned, 1.0, 0.05);
}

// A new random command every 2 s (seeded) for 60 s: no fall.
TEST(MotionPhysics, RandomCommandsNoFall) {
  MotionHarness h(14, 0.0, 0.0, 0.0);
  uint64_t x = 14;
  auto rnd = [&x]() {  // uniform in [-1, 1)
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    return 2.0 * static_cast<double>(x >> 11) / 9007199254740992.0 - 1.0;
  };
  bool ok = true;
  int falls = 0;
  for (int i = 0; i < 30; ++i) {
    h.request(ActionType::WALK, 300 * rnd(), 200 * rnd(), 0.8 * rnd());
    const bool up = h.run(2.0);
    if (!up) ++falls;
    ok = ok && up;
  }
  std::printf("[motion] random commands 60 s: %d two-second spans with a fall\n", falls);
  EXPECT_TRUE(ok);
  // Clipping over the whole run: no command beyond a limit or a per-tick step.
  EXPECT_EQ(h.checked().limit_violations, 0);
  EXPECT_EQ(h.checked().speed_violations, 0);
  EXPECT_GT(h.checked().ticks, 5900);
}

// Walk to a point 2 m ahead using only odometry, then stop: error <= 150 mm.
TEST(MotionPhysics, WalkToPointByOdometry) {
  MotionHarness h(15, -3.0, 0.0, 0.0);
  h.request(ActionType::STAND);
  ASSERT_TRUE(h.run(1.0));
  const Pose2 p0 = h.pose();
  const auto o0 = h.state().odometry;
  const double goal = 2000;  // mm ahead
  bool ok = true;
  for (int i = 0; i < 3000; ++i) {
    const auto o = h.state().odometry;
    // Goal in the robot's current odometry frame (mm).
    const double gx = p0.x * 0 + goal - (o.x - o0.x), gy = -(o.y - o0.y);
    const double c = std::cos(o.theta - o0.theta), s = std::sin(o.theta - o0.theta);
    const double rx = c * gx + s * gy, ry = -s * gx + c * gy;
    const double dist = std::hypot(rx, ry);
    if (dist < 30) break;
    const double speed = std::min(300.0, 1.5 * dist);
    h.request(ActionType::WALK, speed * rx / dist, speed * ry / dist, std::max(-0.5, std::min(0.5, std::atan2(ry, rx))));
    ok = h.run(0.1) && ok;
  }
  h.request(ActionType::STAND);
  ok = h.run(2.0) && ok;
  double fwd, left;
  relative(p0, h.pose(), &fwd, &left);
  const double err = std::hypot(fwd * 1000 - goal, left * 1000);
  std::printf("[motion] walk to 2 m by odometry: ended at (%.0f, %.0f) mm, error %.0f mm\n", fwd * 1000, left * 1000, err);
  EXPECT_TRUE(ok);
  EXPECT_LE(err, 150);
}

// Odometry error after 3 m of walking: <= 10 %.
TEST(MotionPhysics, OdometryAfterThreeMetres) {
  MotionHarness h(16, -4.0, 0.0, 0.0);
  h.request(ActionType::STAND);
  ASSERT_TRUE(h.run(1.0));
  const Pose2 p0 = h.pose();
  const auto o0 = h.state().odometry;
  h.request(ActionType::WALK, 250, 0, 0);
  bool ok = true;
  double travelled = 0;
  for (int i = 0; i < 300 && travelled < 3.0; ++i) {
    ok = h.run(0.1) && ok;
    const Pose2 p = h.pose();
    travelled = std::hypot(p.x - p0.x, p.y - p0.y);
  }
  h.request(ActionType::STAND);
  ok = h.run(2.0) && ok;
  const Pose2 p1 = h.pose();
  const auto o1 = h.state().odometry;
  // Both in the start frame: truth from the field, estimate from odometry.
  double tf, tl;
  relative(p0, p1, &tf, &tl);
  const double ex = (o1.x - o0.x) / 1000, ey = (o1.y - o0.y) / 1000;
  const double err = std::hypot(ex - tf, ey - tl), dist = std::hypot(tf, tl);
  std::printf("[motion] odometry over %.2f m: estimate (%.2f, %.2f) truth (%.2f, %.2f), error %.0f %%\n", dist, ex, ey,
              tf, tl, err / dist * 100);
  EXPECT_TRUE(ok);
  EXPECT_LE(err, 0.1 * dist);
}

// No calibration (every walk gain 1.0): forward 100 mm/s reaches >= 90 % (seeds 21-22, 8 s),
// and forward 200 + left 100 mm/s is within 10 % on each axis with a heading
// drift under 0.005 rad/s (seeds 23-24, 10 s). Bench seeds 1-5 differ; the
// walk's heading hold was tuned on seeds 40-79.
TEST(MotionPhysics, WalkSlowForwardAndCombined) {
  for (uint64_t seed : {21, 22}) {
    MotionHarness h(seed);
    bool ok;
    const simswift::WalkFigures f = walkMeasured(h, 100, 0, 0, 8.0, &ok);
    std::printf("[motion] forward 100 mm/s x 8 s, seed %llu: %.0f %%\n", static_cast<unsigned long long>(seed),
                f.forward_ratio * 100);
    EXPECT_TRUE(ok);
    EXPECT_GE(f.forward_ratio, 0.9) << "seed " << seed;
  }
  for (uint64_t seed : {23, 24}) {
    MotionHarness h(seed);
    // The heading every tick (unwrapped, rad) for its least-squares slope: the meter's.
    bool ok;
    const simswift::WalkFigures f = walkMeasured(h, 200, 100, 0, 10.0, &ok);
    const double slope = f.heading_slope, turned = f.turn * 10;  // rad/s, rad
    const double fwd = f.forward * 10 / 1000, left = f.left * 10 / 1000;  // m
    std::printf(
        "[motion] forward 200 + left 100 mm/s x 10 s, seed %llu: forward %.2f, left %.2f, drift %.1f mrad/s "
        "(least-squares slope %.1f mrad/s)\n",
        static_cast<unsigned long long>(seed), fwd / 10 / 0.2, left / 10 / 0.1, turned / 10 * 1000, slope * 1000);
    EXPECT_TRUE(ok);
    EXPECT_NEAR(fwd / 10 / 0.2, 1.0, 0.1) << "seed " << seed;
    EXPECT_NEAR(left / 10 / 0.1, 1.0, 0.1) << "seed " << seed;
    // Drift: the slope of the heading over the 10 s. The torso also yaws
    // back and forth by 0.01-0.02 rad within each walk cycle, so the bare
    // end-to-start difference / 10 s depends on where in the cycle the 10 s
    // end (seeds 23, 24: 2.0 / 3.5 mrad/s, bench seed 4: 3.2, with slopes of
    // 0.1-1.0; on the physics before the hinge-stop change tuning seeds 60-79
    // reached 5.9 end-to-start with slopes under 1.8). Both are held to the
    // target of 0.005 rad/s here.
    // TODO: a smaller in-cycle yaw swing would make the
    // end-to-start figure as steady as the slope on every seed.
    EXPECT_LT(std::fabs(slope), 0.005) << "seed " << seed;
    EXPECT_LT(std::fabs(turned / 10), 0.005) << "seed " << seed;
  }
}

// Over a 20 s walk at 300 mm/s the hinge anchors stay within
// 0.5 mm of each other (JointProjector) and the stance feet slide less than
// 2 mm per step on average (the sole's friction anchors). Seeds 31-32; the
// bench walks seed 5.
TEST(MotionPhysics, JointsHoldAndSolesStickOverA20sWalk) {
  for (uint64_t seed : {31, 32}) {
    MotionHarness h(seed, -3.5, 0.0, 0.0);
    h.request(ActionType::WALK, 300, 0, 0);
    bool ok = h.run(2.0);
    simswift::WalkMeter meter;  // the stance slip: the walk test kit's
    meter.begin(simswift::api::walkSample(h.runner(), 0), {300, 0, 0});
    double separation = 0;  // m
    for (int i = 0; i < 2000; ++i) {
      ok = h.run(0.01) && ok;
      separation = std::max(separation, h.runner().world().robot(0).anchorSeparation());
      meter.add(simswift::api::walkSample(h.runner(), 0));
    }
    const simswift::WalkFigures slip = meter.figures();
    std::printf("[motion] 20 s walk, seed %llu: hinge anchors apart <= %.2f mm; stance slip mean %.2f, max %.2f mm "
                "over %d steps\n",
                static_cast<unsigned long long>(seed), separation * 1000, slip.slip_mean, slip.slip_max, slip.stances);
    EXPECT_TRUE(ok) << "fell";
    EXPECT_LT(separation, 0.0005) << "seed " << seed;
    EXPECT_LT(slip.slip_mean, 2.0) << "seed " << seed;  // mm
    EXPECT_GT(slip.stances, 60);  // about 4 steps per second
  }
}
