// Small 2-D geometry for behaviour: points and poses on the field.
// Units: mm and rad. Field frame: origin at the centre spot, x toward the
// opponent goal, y to the left, theta counter-clockwise from +x.
#pragma once

#include <cmath>

namespace agent::behaviour {

constexpr double kPi = 3.14159265358979323846;

struct Point2 {
  double x = 0;  // mm
  double y = 0;  // mm
};

struct Pose2 {
  double x = 0;      // mm
  double y = 0;      // mm
  double theta = 0;  // rad
};

inline double wrapAngle(double a) {  // to (-pi, pi]
  a = std::fmod(a + kPi, 2 * kPi);
  if (a <= 0) a += 2 * kPi;
  return a - kPi;
}

inline double distance(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }
inline Point2 position(const Pose2& p) { return {p.x, p.y}; }

// A field point expressed in the robot frame of `pose` (x forward, y left).
inline Point2 toRobotFrame(const Pose2& pose, Point2 field) {
  const double dx = field.x - pose.x, dy = field.y - pose.y;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  return {c * dx + s * dy, -s * dx + c * dy};
}

}  // namespace agent::behaviour
