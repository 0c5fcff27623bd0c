// timing.md: the wall clock of a results folder, per trial and summed:
// real-time factor (simulated s / wall s of one trial in one worker, i.e.
// per core) and peak memory. Depends on the machine and its load, so it
// stays apart from the results.
#pragma once

#include <string>
#include <vector>

#include "app/experiment/Experiment.hpp"
#include "app/experiment/Report.hpp"
#include "app/experiment/Trial.hpp"

namespace simswift::experiment {

// `run` (may be null): the run that completed the folder.
std::string timingMarkdown(const Experiment& e, const std::vector<TrialResult>& results, const RunWall* run);

}  // namespace simswift::experiment
