// A swept experiment's results per cell (Sweep.hpp): one row per cell and
// setup, pooled over the ball positions, with the report's statistics
// (Statistics.hpp): the Wilson 95 % interval of the find rate and a seeded
// percentile bootstrap interval of the mean find time. Written to
// cells.csv and to report.md's sweep section; Figures plots them per swept
// path.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/experiment/Experiment.hpp"
#include "app/experiment/Statistics.hpp"
#include "app/experiment/Trial.hpp"

namespace simswift::experiment {

struct CellRow {
  int cell = 0;
  int setup = 0;                  // index into Experiment::setups
  int first_trial = 0, last_trial = 0;  // the cell's trials (all setups)
  int tests = 0, found = 0;       // trials of this setup that ran (failed ones left out), finds
  stats::Interval rate;           // Wilson 95 % of found / tests
  std::vector<double> times;      // s since PLAYING, of the finds
  double mean_s = 0;              // mean of times (0 without finds)
  stats::Interval mean_ci;        // bootstrap 95 % ([0, 0] without finds)
  uint64_t bootstrap_seed = 0;    // a pure function of (experiment seed, cell, setup)
};

// Cell-major, setups in file order. `results` sorted by trial.
std::vector<CellRow> cellRows(const Experiment& e, const std::vector<TrialResult>& results);

// cells.csv: cell, one column per swept path, setup, trials, finds, rate
// and interval, mean find s and interval, the bootstrap's seed.
std::string cellsCsv(const Experiment& e, const std::vector<CellRow>& rows);

// report.md's sweep section: what was swept, the trial seeds (the same in
// every cell), the cells table and links to the figures.
std::string sweepSection(const Experiment& e, const std::vector<CellRow>& rows);

// figures/sweep_<path with _ for .>.png: the file name (no folder) of a
// swept path's figure.
std::string sweepFigureName(const SweepAxis& axis);

}  // namespace simswift::experiment
