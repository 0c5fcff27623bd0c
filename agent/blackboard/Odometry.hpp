// Dead-reckoned motion of the robot, written by Motion.
// Units: mm, rad.
#pragma once

namespace agent::blackboard {

// Accumulated since Motion started, in the robot frame integrated step by
// step (x forward mm, y left mm, turn rad).
struct Odometry {
  double forward = 0;  // mm
  double left = 0;     // mm
  double turn = 0;     // rad
  // Field-style integration of the same steps: position of the robot in the
  // frame it had when Motion started (mm, mm, rad). Easier for a caller that
  // wants "where am I relative to where I began".
  double x = 0, y = 0, theta = 0;
};

}  // namespace agent::blackboard
