// A scenario test file (`simswift test FILE`, docs/testing.md), loaded from
// YAML and validated whole before anything runs:
//
//   name: reference                 # names the results folder and the report
//   seed: 1                         # every run's seed derives from it and the test's name
//   defaults: {seeds: 20, required: 0.8, time_limit: 60}   # optional, for every test
//   tests:
//     - name: striker_kickoff       # [A-Za-z0-9_.-]+, unique
//       scenario: {...}             # a scenario's keys (docs/runner.md), or the
//                                   # name of a scenario file (relative to this file);
//                                   # its duration is the time limit
//       seeds: 20                   # runs, each with its own seed
//       short: {seeds: 10}          # the CI form (--short); default: the same
//       time_limit: 60              # s of simulated time per run
//       required: 0.9               # pass rate the test must reach (0..1]
//       fuzz:                       # start-pose fuzzing, drawn per seed
//         robots: {x: 0.2, y: [-0.1, 0.3], theta: 0.3}   # every robot; or a list, one per
//                                   # robot (m, m, rad: +-a, or offsets [lo, hi])
//         ball: {x: 0.1, y: 0.1}
//       pass: {...}                 # the pass condition (Condition.hpp)
//
// Every error is a ConfigError "file:line: key: message", with "did you
// mean" for a misspelt key. A required rate that its seeds could not
// confirm even if every run passed (Summary.hpp: the Wilson interval's lower
// end) is refused with the seeds it needs. Every run's fuzzed placement is checked against
// the field before any run starts.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "sim/runner/Scenario.hpp"
#include "app/scenario_tests/Condition.hpp"

namespace simswift::scenario_tests {

// Runs one file may ask for (summed over its tests); more is refused.
constexpr int64_t kMaxRuns = 100000;

struct Range2 {
  double lo = 0, hi = 0;  // offsets added to the start value
  bool any() const { return lo != 0 || hi != 0; }
};

struct PoseFuzz {
  Range2 x, y, theta;  // m, m, rad
};

// A test's settings when neither it nor the file's `defaults:` gives them.
struct TestDefaults {
  int seeds = 20;
  double required = 0.8;   // 20 of 20 passes give a Wilson lower end of 0.84
  double time_limit = 60;  // s
};

struct ScenarioTest {
  std::string name;
  std::string definition;        // what it measures, as flow YAML: its entry without name, seed
                                 // counts, required rate and its robots' programs and behaviours
                                 // (a baseline's test is compared only if its own is the same)
  int line = 0;                  // of the test's entry
  runner::Scenario scenario;     // duration = time_limit
  FieldConfig field;             // the scenario's field (for the predicates)
  int seeds = TestDefaults{}.seeds;
  int short_seeds = TestDefaults{}.seeds;
  double time_limit = TestDefaults{}.time_limit;  // s
  double required = TestDefaults{}.required;      // pass rate
  std::vector<PoseFuzz> robot_fuzz;  // one per robot (zero ranges: none)
  PoseFuzz ball_fuzz;            // x, y
  TimeNode pass;
};

struct TestFile {
  std::string source;            // file name, for messages
  std::string text;              // its text (kept in the results folder)
  std::string name;
  uint64_t seed = 1;
  std::vector<ScenarioTest> tests;

  static TestFile loadFile(const std::string& path);
  static TestFile parse(const std::string& text, const std::string& source_name);
};

// Keeps only the tests named in `names` ("a,b,c"), in the file's order.
// False with *error naming an unknown test.
bool selectTests(TestFile& f, const std::string& names, std::string* error);

// Which test and run a global run index is (tests in file order, each's
// runs in order). `short_form`: the short seed counts.
struct RunSpec {
  int index = 0;
  int test = 0;
  int run = 0;
  uint64_t seed = 0;  // < 2^31, as published run seeds have been (DeriveSeed.hpp)
};
int countRuns(const TestFile& f, bool short_form);
RunSpec runSpec(const TestFile& f, bool short_form, int index, uint64_t seed_override, bool has_override);

// Each test's definition (ScenarioTest::definition) in a test file's text,
// by name (a baseline folder's tests.yaml; its tests are not loaded). Throws
// ConfigError if the text is not a test file.
std::map<std::string, std::string> testDefinitions(const std::string& text, const std::string& source);

// The run's seed: from the file's seed (or --seed), the test's name and
// the run's number; a test's seeds do not move when tests are added,
// removed or reordered.
uint64_t runSeed(uint64_t file_seed, const std::string& test, int run);

// The test's scenario for one run: its seed set and start poses fuzzed.
runner::Scenario runScenario(const ScenarioTest& t, uint64_t seed);

}  // namespace simswift::scenario_tests
