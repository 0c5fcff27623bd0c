#include "agent/perception/BallTracker.hpp"

#include <algorithm>
#include <cmath>

namespace agent::perception {

void BallTracker::start(double x, double y, double r) {
  for (auto [a, z] : {std::pair<Axis*, double>{&ax_, x}, {&ay_, y}}) {
    a->p = z;
    a->v = 0;
    a->P[0][0] = r * r;
    a->P[0][1] = a->P[1][0] = 0;
    a->P[1][1] = cfg_.initial_speed_sd * cfg_.initial_speed_sd;
  }
  tracking_ = true;
}

void BallTracker::predict(double dt) {
  if (dt <= 0) return;
  // Rolling friction: the speed drops by deceleration * dt, not below zero.
  const double speed = std::hypot(ax_.v, ay_.v);
  const double k = speed > 1e-9 ? std::max(0.0, speed - cfg_.deceleration * dt) / speed : 0.0;
  const double q = cfg_.accel_noise * cfg_.accel_noise;
  for (Axis* a : {&ax_, &ay_}) {
    // Position advances by the mean velocity over the step.
    a->p += 0.5 * (a->v + k * a->v) * dt;
    a->v *= k;
    // F = [[1, dt], [0, 1]], white-acceleration process noise.
    const double p00 = a->P[0][0] + dt * (a->P[1][0] + a->P[0][1]) + dt * dt * a->P[1][1];
    const double p01 = a->P[0][1] + dt * a->P[1][1];
    const double p11 = a->P[1][1];
    a->P[0][0] = p00 + q * dt * dt * dt * dt / 4;
    a->P[0][1] = a->P[1][0] = p01 + q * dt * dt * dt / 2;
    a->P[1][1] = p11 + q * dt * dt;
  }
}

void BallTracker::correct(double x, double y, double r) {
  for (auto [a, z] : {std::pair<Axis*, double>{&ax_, x}, {&ay_, y}}) {
    const double s = a->P[0][0] + r * r;
    const double k0 = a->P[0][0] / s, k1 = a->P[1][0] / s;
    const double e = z - a->p;
    a->p += k0 * e;
    a->v += k1 * e;
    const double p00 = (1 - k0) * a->P[0][0], p01 = (1 - k0) * a->P[0][1];
    const double p11 = a->P[1][1] - k1 * a->P[0][1];
    a->P[0][0] = p00;
    a->P[0][1] = a->P[1][0] = p01;
    a->P[1][1] = p11;
  }
}

void BallTracker::update(double time, double forward, double left, double turn,
                         const blackboard::VisionMeasurements& vision, const blackboard::LocalisationEstimate& pose,
                         const blackboard::TeamInfo& team) {
  const double dt = last_time_ < 0 ? 0 : std::max(0.0, time - last_time_);
  last_time_ = time;
  if (tracking_) {
    // The robot moved: express the ball in the new robot frame. Position
    // shifts and turns; the ground velocity only turns.
    const double c = std::cos(-turn), s = std::sin(-turn);
    const double px = ax_.p - forward, py = ay_.p - left;
    ax_.p = c * px - s * py;
    ay_.p = s * px + c * py;
    const double vx = ax_.v, vy = ay_.v;
    ax_.v = c * vx - s * vy;
    ay_.v = s * vx + c * vy;
    // The covariance: rotate the position and velocity blocks alike; the
    // per-axis form drops the small cross terms, so inflate a little instead.
    const double grow = std::fabs(turn) * std::hypot(ax_.p, ay_.p);
    ax_.P[0][0] += grow * grow;
    ay_.P[0][0] += grow * grow;
    predict(dt);
  }
  est_.seen_this_frame = false;
  if (vision.ball_seen) {
    const double x = vision.ball.x, y = vision.ball.y;
    const double r = cfg_.measure_floor + cfg_.measure_fraction * std::hypot(x, y);
    const double gx = (x - ax_.p) * (x - ax_.p) / (ax_.P[0][0] + r * r);
    const double gy = (y - ay_.p) * (y - ay_.p) / (ay_.P[0][0] + r * r);
    if (!tracking_ || gx + gy > cfg_.gate * cfg_.gate)
      start(x, y, r);  // first sight, or a different ball (or a jump): restart
    else
      correct(x, y, r);
    last_seen_ = time;
    est_.seen_this_frame = true;
  }
  est_.time = time;
  est_.time_since_seen = last_seen_ < 0 ? 1e9 : time - last_seen_;
  if (tracking_ && est_.time_since_seen > cfg_.lost_after) tracking_ = false;
  est_.valid = tracking_;
  est_.rr_x = ax_.p;
  est_.rr_y = ay_.p;
  est_.rr_vx = ax_.v;
  est_.rr_vy = ay_.v;
  est_.sd_position = std::sqrt(0.5 * (ax_.P[0][0] + ay_.P[0][0]));
  // Field ball through the pose estimate.
  const double c = std::cos(pose.pose.theta), s = std::sin(pose.pose.theta);
  est_.x = pose.pose.x + c * ax_.p - s * ay_.p;
  est_.y = pose.pose.y + s * ax_.p + c * ay_.p;
  est_.vx = c * ax_.v - s * ay_.v;
  est_.vy = s * ax_.v + c * ay_.v;
  // Team ball: the freshest teammate's ball, aged by the time since it came.
  est_.team_valid = false;
  est_.team_age = 1e9;
  est_.team_player = -1;
  for (int p = 1; p <= blackboard::kMaxTeammates; ++p) {
    const blackboard::TeammateReport& m = team.mates[p];
    if (!m.valid || p == team.player_number) continue;
    const double age = m.ball_age + std::max(0.0, time - m.received);
    if (age > cfg_.team_ball_max_age || age >= est_.team_age) continue;
    // Where it will have rolled by now (the same friction model).
    const double speed = std::hypot(m.ball_vx, m.ball_vy);
    const double t = std::max(0.0, time - m.received);
    const double t_stop = speed / cfg_.deceleration;
    const double tt = std::min(t, t_stop);
    const double travel = speed * tt - 0.5 * cfg_.deceleration * tt * tt;
    est_.team_valid = true;
    est_.team_age = age;
    est_.team_player = p;
    est_.team_x = m.ball_x + (speed > 1e-9 ? m.ball_vx / speed * travel : 0);
    est_.team_y = m.ball_y + (speed > 1e-9 ? m.ball_vy / speed * travel : 0);
  }
  if (!est_.valid && est_.team_valid) {
    // Not seen ourselves: the team's ball, in our frame, for behaviour.
    const double dx = est_.team_x - pose.pose.x, dy = est_.team_y - pose.pose.y;
    est_.x = est_.team_x;
    est_.y = est_.team_y;
    est_.rr_x = c * dx + s * dy;
    est_.rr_y = -s * dx + c * dy;
  }
}

}  // namespace agent::perception
