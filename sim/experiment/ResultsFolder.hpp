// The results folder of a batch (layout: Batch.hpp): whose it is, which
// trials are done, which trial files it holds. trialFile() names them
// (declared in Batch.hpp, which tests use).
#pragma once

#include <string>
#include <vector>

#include "sim/experiment/Experiment.hpp"

namespace simswift::experiment {

// Creates dir/trials and claims the folder for `e`: its text is written
// once to dir/experiment.yaml, then must match (BatchError if not).
// Removes temporary files of writers that died mid-write.
void claimFolder(const Experiment& e, const std::string& dir);

// A trial is done once its results row (trial_NNNNNN.csv, written last) is there.
bool trialDone(const std::string& dir, int trial);

// The trial files in a trials/ folder, sorted: no temporary files, no logs.
std::vector<std::string> listTrialFiles(const std::string& trials_dir);

}  // namespace simswift::experiment
