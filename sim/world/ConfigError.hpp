// The error every configuration loader (field, scenario) throws for bad
// input. Its message always names the file, the line and the key path, e.g.
//   fields/x.yaml:12: field.ball.mass: must be > 0 (got -1)
#pragma once

#include <stdexcept>

namespace simswift {

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace simswift
