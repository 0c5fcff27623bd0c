// Per test: the pass count over its runs, the Wilson 95 % interval of the
// pass rate, the verdict against the required rate, and (with a baseline)
// whether it regressed beyond chance.
//
// Verdict: "passes" when the interval's lower end reaches the required
// rate, "fails" when its upper end is below it, otherwise "undecided: run
// more seeds".
//
// Regression against a baseline (an earlier run's results.csv), one-sided
// (worse now). Paired when the two share run seeds (the same file seed, as
// the CI templates run main and the change: run i starts from the same
// placement and noise on both sides): the runs with the same seed are the
// pairs, the pass rate by McNemar's exact test on them, the time to pass by
// the Wilcoxon signed-rank test on the pairs that passed on both sides (a
// pair that failed on either side is the rate test's evidence, not the
// time's; equal times are dropped, as the test does). Independent when they
// share none (other seeds): the pass rate by Fisher's exact test, the times
// to pass by Mann-Whitney (the passing runs of each, when both have at
// least two). Every comparison of the file is one family: the p-values are
// Holm-adjusted, and a regression is called when an adjusted p-value is
// below alpha (default 0.05), so a whole unchanged program is flagged at
// most alpha of the time however many tests the file holds.
#pragma once

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "app/scenario_tests/TestRun.hpp"

namespace simswift::scenario_tests {

struct TestSummary {
  std::string name;
  double required = 0;
  int runs = 0, passed = 0;
  double lo = 0, hi = 1;            // Wilson 95 % interval of the pass rate
  enum class Verdict { Passes, Fails, Undecided } verdict = Verdict::Undecided;
  std::vector<RunResult> failures;  // in run order
  double mean_pass_s = 0;           // mean time to pass over the passing runs (s)
  double sim_s = 0, wall_s = 0;     // summed over runs (reporting only)
  // Against the baseline (compared = the baseline has this test).
  bool compared = false;
  bool changed = false;                   // in the baseline, but defined differently there
  int base_runs = 0, base_passed = 0;
  double base_mean_pass_s = 0;
  int pairs = 0;                          // runs paired by seed with the baseline's (0: independent)
  double p_rate = 1, p_time = 1;          // one-sided, raw
  double p_rate_adj = 1, p_time_adj = 1;  // Holm-adjusted over the file
  bool time_compared = false;
  bool regressed = false;

  double rate() const { return runs ? static_cast<double>(passed) / runs : 0; }
};

const char* verdictName(TestSummary::Verdict v);  // "passes", "fails", "undecided: run more seeds"

// Summaries in the file's test order from every run's result (any order).
std::vector<TestSummary> summarise(const TestFile& f, const std::vector<RunResult>& results);

// Fills the baseline fields from this run's and the baseline's results
// (tests matched by name; a test missing from the baseline, or `changed`
// since (its definition differs), is not compared).
void compareWithBaseline(std::vector<TestSummary>& tests, const std::vector<RunResult>& current,
                         const std::vector<RunResult>& baseline, double alpha,
                         const std::set<std::string>& changed = {});

// 0 every test passes and none regressed; 1 otherwise.
int exitCode(const std::vector<TestSummary>& tests);

}  // namespace simswift::scenario_tests
