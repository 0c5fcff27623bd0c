// One timed body action of an `actions:` list, as a scenario and the robot
// program's config file write it (agent/behaviour/ActionsBehaviour.hpp plays them):
//
//   {t: 1, action: walk, forward: 300, left: 0, turn: 0}       # mm/s, mm/s, rad/s
//   {t: 6, action: kick, foot: right, power: 1, direction: 0}  # direction rad
//   {t: 9, action: stand, head_yaw: 0.5, head_pitch: 0}        # rad
//
// Actions: walk, stand, kick, getup_front, getup_back, dead, crouch, limp,
// none. Speeds beyond the walk's own limits (WalkConfig) are refused, not
// clamped. Errors name file, line and key (common/config/ConfigError.hpp).
#pragma once

#include <string>
#include <vector>

#include "common/config/YamlReader.hpp"
#include "agent/motion/ActionScript.hpp"

namespace agent::motion {

// The action names, as the files write them.
const std::vector<std::string>& actionNames();

// The body action of entry `r` at simulated time t_s (the caller read `t`);
// reads every action key and finishes the map.
ActionStep readBodyAction(const common::config::YamlReader& r, double t_s);

// The same entry as YAML flow text, read back exactly by readBodyAction.
std::string bodyActionYaml(const ActionStep& a);

}  // namespace agent::motion
