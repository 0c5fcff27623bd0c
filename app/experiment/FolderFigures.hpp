// The figures/ of a results folder (drawn by Figures.hpp): per setup the
// robots' routes and the find times, per swept path the sweep figure. A
// figure gnuplot could not draw is a note, not an error.
#pragma once

#include <string>
#include <vector>

#include "app/experiment/Experiment.hpp"
#include "app/experiment/SweepReport.hpp"
#include "app/experiment/Trial.hpp"

namespace simswift::experiment {

// Creates dir/figures; routes_<setup>.png from `tracks` (tracks.csv's
// text, header first) and findtime_<setup>.png from `results`.
void writeSetupFigures(const Experiment& e, const std::string& dir, const std::vector<TrialResult>& results,
                       const std::string& tracks, std::string* notes);

// sweep_<path>.png in dir/figures for every swept path, from the cells table.
void writeSweepFigures(const Experiment& e, const std::string& dir, const std::vector<CellRow>& rows,
                       std::string* notes);

}  // namespace simswift::experiment
