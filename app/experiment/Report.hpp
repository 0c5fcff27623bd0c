// The experiment's Markdown report, laid out like the thesis's tables
// 5.3-5.8 (one per setup) and comparisons 5.9-5.12 (ours beside the
// thesis's, from ThesisTables).
//
// Per position, as the thesis computes them: Tests; Found; Not Found; Total
// Seconds = sum of the find times; Avg. Seconds = Total / Found (0 when none
// found); Std. Dev. = population standard deviation of the find times (0
// for fewer than two; the thesis prints 0.00 for a single find). Summary
// rows: "Total" rows sum the counts; "Average" rows are the plain mean of
// each column over the position rows (so the thesis's 75.00 in table 5.3
// is the mean of five position averages, not a mean over finds).
#pragma once

#include <string>
#include <vector>

#include "app/experiment/Experiment.hpp"
#include "app/experiment/Trial.hpp"

namespace simswift::experiment {

struct PositionStats {
  int position = 0;
  int tests = 0, found = 0, not_found = 0;
  double total_s = 0, avg_s = 0, sd_s = 0;
};
PositionStats positionStats(int position, int tests, const std::vector<double>& found_times);

struct SummaryRow {
  double tests = 0, found = 0, not_found = 0, total_s = 0, avg_s = 0, sd_s = 0;
};
SummaryRow sumRows(const std::vector<PositionStats>& rows);
SummaryRow meanRows(const std::vector<PositionStats>& rows);

// Setup `setup`'s rows in the experiment's ball order.
std::vector<PositionStats> setupTable(const Experiment& e, const std::vector<TrialResult>& results, int setup);

// Groups of consecutive positions (in ball order) for the summary rows:
// chunks of five (the thesis's 1-5 and 6-10); one chunk gives "Total" /
// "Average" rows (tables 5.5-5.8), several give "Sub-" rows and a "Grand" one.
std::vector<std::pair<int, int>> summaryGroups(int rows);  // [first, last) row indices

// The whole report's deterministic part (everything but the wall clock).
// `results` sorted by trial, one per trial.
std::string reportMarkdown(const Experiment& e, const std::vector<TrialResult>& results);
// Its statistics section (ReportStatistics.cpp): 95 % intervals per cell and
// setup, Fisher and Mann-Whitney tests between setups, in words.
std::string statisticsSection(const Experiment& e, const std::vector<TrialResult>& results);

// The wall clock of a batch invocation (runBatch), for the timing part.
struct RunWall {
  int jobs = 0;         // worker processes
  int ran = 0;          // trials this invocation ran
  double wall_s = 0;    // s, from its first trial launched to its last one done
  double trial_wall_s = 0, trial_sim_s = 0;  // summed over those trials
  double peak_trial_mb = 0;  // MB: the largest peak resident memory of one trial process
};

// The report's last section, headed kWallClockHeading: real-time factor
// (simulated s / wall s of a trial in one worker, i.e. per core) per setup
// and overall, and the invocation's wall time if `run` is given. The only
// part of report.md that differs between runs; deterministicPart() cuts it off.
extern const char* const kWallClockHeading;
std::string wallClockSection(const Experiment& e, const std::vector<TrialResult>& results, const RunWall* run);
std::string deterministicPart(const std::string& report);

}  // namespace simswift::experiment
