// A robot's `behaviour:` in a scenario or in the robot program's own config
// file (agent/behaviour/BehaviourConfig.hpp):
//
//   behaviour: findball2017            # or another kind (kBehaviourKinds), or script
//   behaviour: {kind: findball2017,    # with overrides of any config field
//               grid: {columns: 4, rows: 3},
//               distribution: {entropy_rate: 0.02},
//               strategy: {distributed: off}, search: {spin_at_point: off},
//               skills: {scan_speed: 1.5}, field: {...}}
//
// Each section's keys are the struct's field names (units as commented
// there: mm, mm/s, rad, rad/s, s); unknown keys and out-of-range values are
// refused naming file, line and field. `script` runs the robot's `actions:`
// list (the scenario's timed body actions) instead of a behaviour.
#pragma once

#include <optional>

#include "agent/behaviour/BehaviourConfig.hpp"
#include "common/config/YamlReader.hpp"

namespace agent::behaviour {

// `behaviour` of robot map `robot` (which must have the key). Returns empty
// for `script`. `yaml` (if not null): the behaviour as flow YAML, kind
// included, to write into another file (a robot program's config).
std::optional<BehaviourConfig> readBehaviour(const common::config::YamlReader& robot, std::string* yaml = nullptr);

// The same from a kind name and the overrides as YAML flow text (e.g.
// "{strategy: {distributed: off}}"; "" = none), for callers holding them
// apart (the experiment's robots). Errors name `source`. Empty for script.
std::optional<BehaviourConfig> behaviourFromText(const std::string& kind,
                                                const std::string& overrides, const std::string& source,
                                                std::string* yaml = nullptr);

}  // namespace agent::behaviour
