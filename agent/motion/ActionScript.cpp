#include "agent/motion/ActionScript.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace agent::motion {

ActionScriptMotion::ActionScriptMotion(std::vector<ActionStep> steps, const MotionConfig& cfg)
    : module_(std::make_unique<MotionModule>(board_, cfg)), steps_(std::move(steps)) {
  std::stable_sort(steps_.begin(), steps_.end(),
                   [](const ActionStep& a, const ActionStep& b) { return a.t < b.t; });
  // Until the first step: stand.
  board_.motion_request.update([](blackboard::MotionRequest& r) { r.body.type = blackboard::ActionType::STAND; });
}

void ActionScriptMotion::tick(const libagent::SensorValues& sensors, int64_t sim_time_us,
                              libagent::JointValues& out) {
  const double t = static_cast<double>(sim_time_us) * 1e-6;
  while (next_ < steps_.size() && steps_[next_].t <= t + 1e-9) {
    const ActionStep& s = steps_[next_++];
    board_.motion_request.update([&](blackboard::MotionRequest& r) {
      r.body = s.body;
      if (s.has_head) r.head = s.head;
      ++r.sequence;  // a new request (a repeated kick kicks again)
    });
  }
  module_->tick(sensors, sim_time_us, out);
}

bool parseActionType(const std::string& name, blackboard::ActionType* out) {
  using blackboard::ActionType;
  std::string n = name;
  for (char& c : n) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (int i = 0; i < static_cast<int>(ActionType::NUM_ACTION_TYPES); ++i) {
    const auto t = static_cast<ActionType>(i);
    if (n == blackboard::actionName(t)) {
      *out = t;
      return true;
    }
  }
  return false;
}

}  // namespace agent::motion
