// `simswift experiment ...`: the command line of the experiment module
// (app/simswift.cpp hands over argv after "experiment").
#pragma once

#include "sim/experiment/TrialHooks.hpp"

namespace simswift::experiment {

extern const char* kExperimentUsage;

// argv[0] is "experiment". Returns the process exit code: 0 done, 1 trial
// or I/O failure, 2 bad command line or experiment file, 130 interrupted.
int experimentMain(int argc, char** argv, const TrialHooks& hooks);

}  // namespace simswift::experiment
