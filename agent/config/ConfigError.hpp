// The error every configuration loader (the simulator's field and scenario, the
// robot program's config) throws for bad
// input. Its message always names the file, the line and the key path, e.g.
//   fields/x.yaml:12: field.ball.mass: must be > 0 (got -1)
#pragma once

#include <stdexcept>

namespace agent::config {

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace agent::config
