// A trial's result (TrialResult: what runTrial, Trial.hpp, returns) and its
// rows in the results folder's files: results.csv (deterministic: a function
// of the experiment file and the trial index), tracks.csv, and timing.csv
// (wall clock and memory: never part of the results).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/experiment/Experiment.hpp"

namespace simswift::experiment {

struct RobotOutcome {
  int team = 0, player = 0;   // SPL numbers
  double distance_m = 0;      // walked (track samples, teleports excluded)
  int falls = 0;              // Runner's fall count
  int contact_falls = 0;      // of falls, those right after touching another robot (runner::FallDetector)
  int sideline_moves = 0;
};

struct TrackSample {
  int robot = 0;              // index in the setup
  double t = 0;               // s since PLAYING
  double x = 0, y = 0, theta = 0;  // m, m, rad; field frame, torso
};

struct TrialResult {
  int trial = 0;
  // With a sweep: the trial's cell and its values, as the sweep lists them
  // (results.csv columns after `trial`); -1 without one (no such columns).
  int cell = -1;
  std::vector<std::string> cell_values;
  std::string setup;
  int position = 0;           // ball position number (table 5.2)
  int repeat = 0;
  uint64_t seed = 0;
  bool found = false;
  double seconds = 0;         // find time (s since PLAYING) if found
  std::string finder;         // "t19p3" if found
  int resets = 0;             // world resets after a numerical blow-up
  // Why the trial failed ("" = it ran): a launched robot program crashed,
  // exited or never attached. A failed trial is neither found nor not found.
  std::string failed;
  std::vector<RobotOutcome> robots;
  std::vector<TrackSample> tracks;
  // Timing (wall clock) and memory, reporting only (they depend on the machine).
  double sim_s = 0, wall_s = 0;
  double peak_mb = 0;  // MB (MiB): peak resident memory of the trial's process, 0 = not recorded
  double realTimeFactor() const { return wall_s > 0 ? sim_s / wall_s : 0; }
};

// results.csv: header for up to `robots` robots, one row per trial. With a
// sweep, `cell` and one column per swept path follow `trial`.
std::string csvHeader(int robots, const std::vector<SweepAxis>& sweep = {});
std::string csvRow(const TrialResult& r, int robots);  // with '\n'
// Parses a csvRow back (tracks and timing stay empty); `swept_paths`: the
// sweep's path count (0 without one). Throws std::runtime_error.
TrialResult parseCsvRow(const std::string& line, int swept_paths = 0);
// tracks.csv
std::string tracksHeader();
std::string tracksRows(const TrialResult& r, const Experiment& e);
// timing.csv (wall clock; peak_mb: the trial process's peak resident memory)
std::string timingHeader();
std::string timingRow(const TrialResult& r);
// Reads sim_s, wall_s and peak_mb (absent in folders written before it: 0)
// of a timingRow into `r`.
void parseTimingRow(const std::string& row, TrialResult& r);

std::string fixed(double v, int decimals);  // "%.*f", locale-free

}  // namespace simswift::experiment
