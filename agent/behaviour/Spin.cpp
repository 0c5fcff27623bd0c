#include "agent/behaviour/Spin.hpp"

#include <algorithm>

namespace agent::behaviour {

Spin::Output Spin::tick(const BehaviourInputs& in) {
  turned_ += wrapAngle(in.self.pose.theta - last_theta_);
  last_theta_ = in.self.pose.theta;
  Output o;
  o.head.yaw = 0;
  o.head.pitch = static_cast<float>(s_.scan_pitch);
  if (turned_ >= 2 * kPi) {
    o.done = true;
    o.body.type = blackboard::ActionType::STAND;
    return o;
  }
  o.body.type = blackboard::ActionType::WALK;
  o.body.turn = static_cast<float>(std::min(s_.spin_speed, in.walk.max_turn));
  return o;
}

}  // namespace agent::behaviour
