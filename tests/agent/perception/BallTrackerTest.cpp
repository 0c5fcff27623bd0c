// The ball tracker: a rolling ball's position and velocity after 1 s of
// noisy detections, odometry compensation, losing the ball, the team ball.
// Claims hold over 20 seeds (1..20).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/random/Random.hpp"
#include "agent/perception/BallTracker.hpp"

namespace bb = agent::blackboard;
namespace perception = agent::perception;

namespace {
constexpr double kFramePeriod = 1.0 / 30;

// A ball rolling on the field from (x, y) at (vx, vy), slowing at `decel`
// (mm, mm/s, mm/s^2). Returns its position at time t.
struct RollingBall {
  double x, y, vx, vy, decel;
  void at(double t, double* px, double* py, double* pvx, double* pvy) const {
    const double v = std::hypot(vx, vy), t_stop = v / decel, tt = std::min(t, t_stop);
    const double s = v * tt - 0.5 * decel * tt * tt, vn = std::max(0.0, v - decel * t);
    *px = x + vx / v * s;
    *py = y + vy / v * s;
    *pvx = vx / v * vn;
    *pvy = vy / v * vn;
  }
};

bb::VisionMeasurements detection(double x, double y, common::random::Random& rng) {
  // The detector model's default: distance noise 8 % (1 sigma), bearing 2 deg.
  const double d = std::hypot(x, y) * (1 + rng.gaussian(0.08)), b = std::atan2(y, x) + rng.gaussian(0.035);
  bb::VisionMeasurements v;
  v.ball_seen = true;
  v.ball.x = static_cast<float>(d * std::cos(b));
  v.ball.y = static_cast<float>(d * std::sin(b));
  return v;
}
}  // namespace

TEST(BallTracker, RollingBallPositionAndVelocityAfterOneSecond) {
  // A ball passing in front of a standing robot: 1.5 m ahead, rolling to its
  // right at 1 m/s (rolling friction 500 mm/s^2, as on the carpet).
  const RollingBall ball{1500, 600, -300, -950, 500};
  std::vector<double> pos_err, vel_err;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    common::random::Random rng(seed);
    perception::BallTracker tr;
    bb::LocalisationEstimate pose;  // robot at the centre spot, facing +x
    bb::TeamInfo team;
    double t = 0;
    for (int i = 0; i <= 30; ++i, t += kFramePeriod) {
      double x, y, vx, vy;
      ball.at(t, &x, &y, &vx, &vy);
      tr.update(t, 0, 0, 0, detection(x, y, rng), pose, team);
    }
    double x, y, vx, vy;
    ball.at(t - kFramePeriod, &x, &y, &vx, &vy);
    const bb::BallEstimate& e = tr.estimate();
    ASSERT_TRUE(e.valid);
    EXPECT_EQ(e.time_since_seen, 0.0);
    pos_err.push_back(std::hypot(e.rr_x - x, e.rr_y - y));
    vel_err.push_back(std::hypot(e.rr_vx - vx, e.rr_vy - vy));
    // Field coordinates: the robot stands at the origin facing +x.
    EXPECT_NEAR(e.x, e.rr_x, 1e-9);
    EXPECT_NEAR(e.vy, e.rr_vy, 1e-9);
  }
  std::sort(pos_err.begin(), pos_err.end());
  std::sort(vel_err.begin(), vel_err.end());
  // Tolerances: position within 100 mm and velocity within 250 mm/s (a
  // quarter of the speed) for 19 of 20 seeds; every seed within 150 / 400.
  EXPECT_LT(pos_err[18], 100.0);
  EXPECT_LT(vel_err[18], 250.0);
  EXPECT_LT(pos_err.back(), 150.0);
  EXPECT_LT(vel_err.back(), 400.0);
}

TEST(BallTracker, CompensatesTheRobotsOwnMotion) {
  // A still ball 1 m ahead; the robot turns left 90 degrees on the spot
  // without seeing it: the ball must end up 1 m to the robot's right.
  common::random::Random rng(5);
  perception::BallTracker tr;
  bb::LocalisationEstimate pose;
  bb::TeamInfo team;
  double t = 0;
  for (int i = 0; i < 30; ++i, t += kFramePeriod) tr.update(t, 0, 0, 0, detection(1000, 0, rng), pose, team);
  for (int i = 0; i < 30; ++i, t += kFramePeriod) tr.update(t, 0, 0, (M_PI / 2) / 30, bb::VisionMeasurements{}, pose, team);
  EXPECT_NEAR(tr.estimate().rr_x, 0, 80);
  EXPECT_NEAR(tr.estimate().rr_y, -1000, 80);
  EXPECT_NEAR(tr.estimate().time_since_seen, 1.0, 2 * kFramePeriod);
  EXPECT_FALSE(tr.estimate().seen_this_frame);
}

TEST(BallTracker, LostAfterFiveSecondsThenTeamBall) {
  common::random::Random rng(7);
  perception::BallTracker tr;
  bb::LocalisationEstimate pose;
  pose.pose = {-1000, 0, 0};
  bb::TeamInfo team;
  team.player_number = 2;
  double t = 0;
  for (int i = 0; i < 10; ++i, t += kFramePeriod) tr.update(t, 0, 0, 0, detection(800, 0, rng), pose, team);
  for (int i = 0; i < 160; ++i, t += kFramePeriod) tr.update(t, 0, 0, 0, bb::VisionMeasurements{}, pose, team);
  EXPECT_FALSE(tr.estimate().valid);
  EXPECT_FALSE(tr.estimate().team_valid);
  // Player 3 reports a ball at (500, 1000) seen 0.5 s before sending; a
  // stale report from player 4 is ignored.
  team.mates[3] = {true, 3, t, false, 0, 0, 0, 500, 1000, 0, 0, 0.5};
  team.mates[4] = {true, 4, t, false, 0, 0, 0, -500, 0, 0, 0, 9.0};
  tr.update(t, 0, 0, 0, bb::VisionMeasurements{}, pose, team);
  const bb::BallEstimate& e = tr.estimate();
  EXPECT_TRUE(e.team_valid);
  EXPECT_EQ(e.team_player, 3);
  EXPECT_NEAR(e.team_age, 0.5, 1e-9);
  EXPECT_NEAR(e.team_x, 500, 1e-9);
  // Behaviour gets it robot-relative through our pose: 1.5 m ahead, 1 m left.
  EXPECT_NEAR(e.rr_x, 1500, 1e-6);
  EXPECT_NEAR(e.rr_y, 1000, 1e-6);
}
