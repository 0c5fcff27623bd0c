// The error of a batch run that is not the experiment file's fault: a
// results folder another run is using, shards that disagree about a trial,
// I/O (exit code 1).
#pragma once

#include <stdexcept>

namespace simswift::experiment {

struct BatchError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A batch refused for what the user gave it (exit code 2, as a bad file):
// a results folder that holds another experiment file's results, shard
// folders of different experiments.
struct BatchInputError : BatchError {
  using BatchError::BatchError;
};

}  // namespace simswift::experiment
