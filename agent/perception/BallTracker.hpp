// The ball tracker: a Kalman filter over the ball's position and velocity
// relative to the robot, with a rolling-friction deceleration, compensated
// for the robot's own motion by odometry; plus the field ball (through the
// pose estimate) and the team ball (teammates' reports).
//
// State: position (mm) in the robot frame and the ball's velocity over the
// ground (mm/s) expressed in the robot frame. Each axis (x, y) is a separate
// 2-state filter [position, velocity]; the axes share the model and the
// odometry rotation couples them only through the state, which is rotated
// exactly (the covariance is rotated as a whole).
//
// Units: mm, mm/s, s, rad.
#pragma once

#include "agent/blackboard/Blackboard.hpp"

namespace agent::perception {

struct BallTrackerConfig {
  double deceleration = 500.0;       // mm/s^2: rolling friction of the ball on carpet
  double accel_noise = 1500.0;       // mm/s^2, 1 sigma of unmodelled acceleration (kicks, bounces)
  double measure_floor = 30.0;       // mm, position noise of a detection: floor + fraction * distance
  double measure_fraction = 0.06;
  double initial_speed_sd = 1000.0;  // mm/s at first sight
  double gate = 5.0;                 // sigmas: farther detections restart the track
  double lost_after = 5.0;           // s unseen: the estimate is dropped (valid = false)
  double team_ball_max_age = 4.0;    // s: older teammates' reports are ignored
};

class BallTracker {
 public:
  explicit BallTracker(const BallTrackerConfig& cfg = {}) : cfg_(cfg) {}

  // One frame at `time` s: the odometry step since the previous frame (robot
  // frame: forward mm, left mm, turn rad), this frame's detection (if any, mm
  // robot-relative), the pose estimate (for the field ball) and the team.
  void update(double time, double forward, double left, double turn, const blackboard::VisionMeasurements& vision,
              const blackboard::LocalisationEstimate& pose, const blackboard::TeamInfo& team);

  const blackboard::BallEstimate& estimate() const { return est_; }

 private:
  struct Axis {
    double p = 0, v = 0;              // mm, mm/s
    double P[2][2] = {{0, 0}, {0, 0}};  // covariance
  };
  void start(double x, double y, double r);
  void predict(double dt);
  void correct(double x, double y, double r);

  BallTrackerConfig cfg_;
  Axis ax_, ay_;
  bool tracking_ = false;
  double last_time_ = -1;
  double last_seen_ = -1;
  blackboard::BallEstimate est_;
};

}  // namespace agent::perception
