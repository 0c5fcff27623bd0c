#include "agent/behaviour/Kick.hpp"

#include <cmath>

namespace agent::behaviour {

void Kick::start(const BehaviourInputs& in) {
  start_ = in.time;
  cmd_ = {};
  cmd_.type = blackboard::ActionType::KICK;
  cmd_.foot = in.ball.relative.y >= 0 ? blackboard::Foot::LEFT : blackboard::Foot::RIGHT;
  const Point2 t = toRobotFrame(in.self.pose, s_.kick_target);
  cmd_.kick_direction = static_cast<float>(std::atan2(t.y, t.x));
  cmd_.kick_power = static_cast<float>(s_.kick_power);
}

Kick::Output Kick::tick(const BehaviourInputs& in) const {
  Output o;
  o.done = in.time - start_ >= s_.kick_duration;
  o.body = cmd_;
  if (o.done) o.body.type = blackboard::ActionType::STAND;
  return o;
}

}  // namespace agent::behaviour
