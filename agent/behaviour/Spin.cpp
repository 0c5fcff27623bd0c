#include "agent/behaviour/Spin.hpp"

#include <algorithm>

namespace agent::behaviour {

double Spin::angle() const {
  if (s_.spin_angle > 0) return s_.spin_angle;
  const double scanned = std::clamp(s_.scan_yaw, 0.0, s_.head_yaw_limit);
  return std::max(0.0, 2 * kPi - scanned - s_.cameraHfov());
}

Spin::Output Spin::tick(const BehaviourInputs& in) {
  turned_ += wrapAngle(in.self.pose.theta - last_theta_);
  last_theta_ = in.self.pose.theta;
  Output o;
  o.head.yaw = 0;
  o.head.pitch = static_cast<float>(s_.scan_pitch);
  if (turned_ >= angle()) {
    o.done = true;
    o.body.type = blackboard::ActionType::STAND;
    return o;
  }
  o.body.type = blackboard::ActionType::WALK;
  o.body.turn = static_cast<float>(std::min(s_.spin_speed, in.walk.max_turn));
  return o;
}

}  // namespace agent::behaviour
