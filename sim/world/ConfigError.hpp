// The simulator reads its configuration files (field, scenario, experiment)
// with the shared foundation's YAML reader and error type (common/config): one
// reader and one error for every file simswift or its robot program reads,
// each error naming the file, the line and the key path.
#pragma once

#include "common/config/ConfigError.hpp"
#include "common/config/YamlReader.hpp"

namespace simswift {

using common::config::ConfigError;
using common::config::ConfigPlace;
using common::config::checkConfigSize;
using common::config::expandedNodes;
using common::config::kMaxConfigBytes;
using common::config::kMaxConfigNodes;
using common::config::Range;
using common::config::YamlReader;

}  // namespace simswift
