// The simulator reads its configuration files (field, scenario, experiment)
// with the robot code's YAML reader and error type (agent/config): one
// reader and one error for every file simswift or its robot program reads,
// each error naming the file, the line and the key path.
#pragma once

#include "agent/config/ConfigError.hpp"
#include "agent/config/YamlReader.hpp"

namespace simswift {

using agent::config::ConfigError;
using agent::config::checkConfigSize;
using agent::config::expandedNodes;
using agent::config::kMaxConfigBytes;
using agent::config::kMaxConfigNodes;
using agent::config::Range;
using agent::config::YamlReader;

}  // namespace simswift
