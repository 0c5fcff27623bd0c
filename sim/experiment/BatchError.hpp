// The error of a batch run that is not the experiment file's fault: a
// results folder of another experiment, shards that disagree, I/O.
#pragma once

#include <stdexcept>

namespace simswift::experiment {

struct BatchError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace simswift::experiment
