// One run of a scenario test: a pure function of (test file, run index,
// seed). Builds the run's scenario (the test's, its seed set, its start
// poses fuzzed), starts the Runner with the robot programs inline, and
// after each tick observes the world's truth (Truth.hpp) and updates the
// pass condition (Condition.hpp), until the condition is decided or the
// time limit is reached.
#pragma once

#include <cstdint>
#include <string>

#include "app/scenario_tests/TestFile.hpp"

namespace simswift::scenario_tests {

struct RunResult {
  int index = 0;               // global run index
  std::string test;
  int run = 0;                 // within the test
  uint64_t seed = 0;
  bool passed = false;
  double decided_s = 0;        // when the condition was decided (s)
  double failure_s = 0;        // the first failure's time (s), if failed
  std::string failure;         // the first temporal operator that failed ("" if passed)
  int falls = 0;               // all robots' falls
  // Wall clock and simulated time: reporting only (never in results.csv).
  double sim_s = 0, wall_s = 0;
};

// Runs it. A launched program that fails is a failed run (failure says why,
// without pids or paths). program_logs: launched programs' logs ("" = the
// scenario's); overview_dir: whole-field overview PNGs of the run ("" = none).
// record_path: the run's MCAP recording (docs/recording.md; "" = none),
// with the goals and the verdict among its events.
RunResult runTest(const TestFile& f, const RunSpec& spec, const std::string& program_logs = "",
                  const std::string& overview_dir = "", const std::string& record_path = "");

// results.csv
std::string resultsHeader();
std::string resultsRow(const RunResult& r);  // with '\n'
RunResult parseResultsRow(const std::string& line);  // throws std::runtime_error

// Every run's fuzzed placement against its field (carpet, goal posts, robots
// apart): ConfigError naming the test's line and the run before any runs.
void checkPlacements(const TestFile& f, bool short_form, uint64_t seed_override, bool has_override);

}  // namespace simswift::scenario_tests
