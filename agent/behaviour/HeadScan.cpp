#include "agent/behaviour/HeadScan.hpp"

#include <algorithm>
#include <cmath>

namespace agent::behaviour {

double HeadScan::amplitude() const { return std::clamp(s_.scan_yaw, 0.0, s_.head_yaw_limit); }
double HeadScan::speed() const { return std::clamp(s_.scan_speed, 1e-3, s_.head_speed_limit); }
double HeadScan::sweepDuration() const { return 4 * amplitude() / speed(); }

double HeadScan::yawAt(double time) const {
  const double a = amplitude();
  if (a <= 0) return 0;
  // Distance travelled along the 4a-long triangle path, from yaw 0 going left.
  const double s = std::fmod(std::max(0.0, time - start_) * speed(), 4 * a);
  if (s < a) return s;
  if (s < 3 * a) return 2 * a - s;
  return s - 4 * a;
}

blackboard::HeadCommand HeadScan::tick(double time) const {
  blackboard::HeadCommand h;
  h.yaw = static_cast<float>(yawAt(time));
  h.pitch = static_cast<float>(s_.scan_pitch);
  // A little faster than the sweep so the head keeps up with its moving target.
  h.yaw_speed = static_cast<float>(std::min(s_.head_speed_limit, s_.scan_lead * speed()));
  h.pitch_speed = static_cast<float>(std::min(s_.head_speed_limit, s_.head_pitch_speed));
  return h;
}

blackboard::HeadCommand headLookAt(Point2 rel, const SkillConfig& s) {
  blackboard::HeadCommand h;
  const double d = std::max(1.0, std::hypot(rel.x, rel.y));
  h.yaw = static_cast<float>(std::clamp(std::atan2(rel.y, rel.x), -s.head_yaw_limit, s.head_yaw_limit));
  h.pitch = static_cast<float>(std::clamp(std::atan2(s.head_height, d) - s.look_pitch_offset, 0.0, s.look_max_pitch));
  h.yaw_speed = static_cast<float>(std::min(s.head_speed_limit, s.look_yaw_speed));
  h.pitch_speed = static_cast<float>(std::min(s.head_speed_limit, s.look_pitch_speed));
  return h;
}

}  // namespace agent::behaviour
