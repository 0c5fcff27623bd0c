#include "agent/motion/ActionYaml.hpp"

#include <cmath>
#include <cstdio>

#include "agent/motion/WalkConfig.hpp"

namespace agent::motion {

using common::config::Range;

const std::vector<std::string>& actionNames() {
  static const std::vector<std::string> names = {"walk", "stand",  "kick", "getup_front", "getup_back",
                                                 "dead", "crouch", "limp", "none"};
  return names;
}

ActionStep readBodyAction(const common::config::YamlReader& r, double t_s) {
  ActionStep a;
  a.t = t_s;
  const std::string name = r.choice("action", "stand", actionNames());
  parseActionType(name, &a.body.type);
  // The walk's own limits (WalkConfig, one home): faster requests are
  // refused rather than clamped in silence.
  const WalkConfig walk;
  a.body.forward = static_cast<float>(r.number("forward", 0.0, Range::closed(-walk.max_forward, walk.max_forward)));
  a.body.left = static_cast<float>(r.number("left", 0.0, Range::closed(-walk.max_left, walk.max_left)));
  a.body.turn = static_cast<float>(r.number("turn", 0.0, Range::closed(-walk.max_turn, walk.max_turn)));
  a.body.kick_power = static_cast<float>(r.number("power", 1.0, Range::closed(0, 1)));
  a.body.kick_direction = static_cast<float>(r.number("direction", 0.0, Range::closed(-M_PI, M_PI)));
  a.body.foot =
      r.choice("foot", "right", {"left", "right"}) == "left" ? blackboard::Foot::LEFT : blackboard::Foot::RIGHT;
  if (r.has("head_yaw") || r.has("head_pitch")) {
    a.has_head = true;
    a.head.yaw = static_cast<float>(r.number("head_yaw", 0.0, Range::closed(-M_PI, M_PI)));
    a.head.pitch = static_cast<float>(r.number("head_pitch", 0.0, Range::closed(-M_PI, M_PI)));
  }
  r.finish();
  return a;
}

std::string bodyActionYaml(const ActionStep& a) {
  // %.17g / %.9g: the shortest forms that read back to the same double / float.
  std::string name = blackboard::actionName(a.body.type);
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  char buf[512];
  std::snprintf(buf, sizeof buf, "{t: %.17g, action: %s, forward: %.9g, left: %.9g, turn: %.9g, power: %.9g, "
                "direction: %.9g, foot: %s",
                a.t, name.c_str(), a.body.forward, a.body.left, a.body.turn, a.body.kick_power, a.body.kick_direction,
                a.body.foot == blackboard::Foot::LEFT ? "left" : "right");
  std::string s = buf;
  if (a.has_head) {
    std::snprintf(buf, sizeof buf, ", head_yaw: %.9g, head_pitch: %.9g", a.head.yaw, a.head.pitch);
    s += buf;
  }
  return s + "}";
}

}  // namespace agent::motion
