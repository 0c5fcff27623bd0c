#include "agent/behaviour/ApproachBall.hpp"

#include <cmath>

#include "agent/behaviour/HeadScan.hpp"

namespace agent::behaviour {

Pose2 ApproachBall::standOff(Point2 ball) const {
  const double dx = s_.kick_target.x - ball.x, dy = s_.kick_target.y - ball.y;
  const double n = std::max(1e-6, std::hypot(dx, dy));
  return {ball.x - dx / n * s_.approach_distance, ball.y - dy / n * s_.approach_distance,
          std::atan2(dy, dx)};
}

ApproachBall::Output ApproachBall::tick(const BehaviourInputs& in, Point2 ball) const {
  const Pose2 goal = standOff(ball);
  Output o;
  const WalkToResult w = walk_.tick(in, {goal.x, goal.y}, goal.theta, s_.approach_tolerance);
  o.body = w.body;
  o.lined_up = w.arrived;
  o.head = headLookAt(toRobotFrame(in.self.pose, ball), s_);
  return o;
}

}  // namespace agent::behaviour
