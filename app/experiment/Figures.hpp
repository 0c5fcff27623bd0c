// The experiment's figures:
//  - routes_<setup>.png: where each robot walked over all trials, as a heat
//    map over the field in the robot's own colour (the thesis's figures 5.2
//    and 5.3), with the start poses and the ball positions. Drawn with Cairo.
//  - findtime_<setup>.png: find-time box plots per ball position, drawn by
//    gnuplot (pngcairo) from a data file and script left beside the PNG.
//  - sweep_<path>.png (swept experiments): find rate and mean find time
//    against each value of one swept path, with their 95 % intervals (the
//    cells table, SweepReport.hpp); one line per setup and combination of
//    the other swept values. Also gnuplot, also with .dat and .gp beside.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "app/experiment/Experiment.hpp"
#include "app/experiment/SweepReport.hpp"
#include "app/experiment/Trial.hpp"

namespace simswift::experiment {

struct RouteSamples {
  std::string player;                           // "t19p2", in setup order
  std::vector<std::pair<double, double>> xy;    // m, field frame
};

// Throws std::runtime_error if the PNG cannot be written.
void drawRoutes(const Experiment& e, int setup, const std::vector<RouteSamples>& robots, const std::string& png);

// Writes DIR/findtime_<setup>.dat and .gp and runs gnuplot on them. Returns
// false with *message if gnuplot is missing or fails (the run goes on).
bool plotFindTimes(const Experiment& e, int setup, const std::vector<TrialResult>& results, const std::string& dir,
                   std::string* message);

// Writes DIR/sweep_<path>.dat and .gp for swept path `axis` (an index into
// e.sweep) and runs gnuplot on them; false with *message as plotFindTimes.
bool plotSweep(const Experiment& e, const std::vector<CellRow>& rows, int axis, const std::string& dir,
               std::string* message);

// Runs gnuplot on DIR/<name>.gp in DIR (relative names: the script is the
// same whatever the folder is called). False with *message if gnuplot is
// missing or fails (`what` names the figure in the message). Also the walk
// test kit's trace plot (app/api/WalkTest.cpp).
bool runGnuplot(const std::string& dir, const std::string& name, const std::string& what, std::string* message);

}  // namespace simswift::experiment
