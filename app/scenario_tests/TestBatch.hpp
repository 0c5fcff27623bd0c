// `simswift test`: every run of a test file as a batch, in forked workers
// (app/experiment/ForkPool.hpp), with shards, resume and merge as an
// experiment has them, then the verdicts, the baseline comparison, the
// report and the JUnit file.
//
// Results folder (default results/tests-<name>, -short for the CI form):
//   tests.yaml          the test file's text and the options that choose the runs
//                       (a rerun with another file or options is refused)
//   trials/trial_NNNNNN.csv          one results row per run (written last: done)
//   trials/trial_NNNNNN.timing.csv   its simulated and wall seconds (never in results)
//   trials/trial_NNNNNN.log          the run's messages, kept only if its process failed
//   recordings/<test>_run<N>.mcap   with --record: the failing runs' (or every run's) recording
//   results.csv         every run: test, seed, passed, when, first failure
//   summary.csv         per test: passes, rate, Wilson interval, verdict (and the
//                       baseline's figures and p-values with --baseline)
//   report.md           the same in words, the failing seeds with their replay
//                       commands, the pass-rate figure; wall clock last
//   pass_rates.png      pass rate and interval per test against its required rate
//   junit.xml           one testcase per test (also written to --junit FILE)
// results.csv, summary.csv and report.md up to its wall-clock section are a
// pure function of the file and the options: the same bytes whatever --jobs,
// shards or interruptions.
#pragma once

#include <string>
#include <vector>

#include "app/scenario_tests/Summary.hpp"

namespace simswift::scenario_tests {

struct TestOptions {
  std::string out_dir;            // results folder (created)
  int jobs = 0;                   // worker processes; 0 = the number of cores
  int shard = 1, shards = 1;      // run the runs with index % shards == shard - 1
  bool short_form = false;        // the CI form: each test's short seed count
  std::string only;               // --only: the tests kept (TestFile::tests already filtered)
  bool has_seed = false;          // --seed: replaces the file's seed
  uint64_t seed = 0;
  std::string baseline;           // an earlier run's results folder ("" = none)
  double alpha = 0.05;            // family-wise level of the regression call
  std::string junit;              // also write the JUnit XML here ("" = only in out_dir)
  std::string command;            // how this file was run, for the replay commands
  bool progress_lines = true;     // a line per run on stderr
  // --record: each run recorded as MCAP (docs/recording.md) into
  // DIR/recordings/, kept for the failing runs only or for all.
  enum class Record { None, Failures, All } record = Record::None;
};

// Where run r's recording goes: DIR/recordings/<test>_run<N>.mcap.
std::string recordingPath(const TestOptions& opt, const RunResult& r);
// " (recording PATH)" when run r failed and its recording is there, else "".
std::string recordingNote(const TestOptions& opt, const RunResult& r);

struct TestOutcome {
  int runs = 0, already = 0, ran = 0, failed = 0;
  bool interrupted = false;
  bool assembled = false;          // every run present: verdicts written
  std::vector<TestSummary> tests;  // when assembled
  std::string message;             // what to tell the user
  int exit_code = 0;               // 0 all pass, nothing regressed; 1 otherwise
};

// Throws ConfigError (bad placements), experiment::BatchInputError (a folder
// of another file or options) or experiment::BatchError (I/O, a folder in use).
TestOutcome runTests(const TestFile& f, const TestOptions& opt);

// Joins shard folders into opt.out_dir; verdicts once every run is there.
TestOutcome mergeTests(const TestFile& f, const std::vector<std::string>& dirs, const TestOptions& opt);

// The text kept as tests.yaml: the file's text and the options that choose
// the runs.
std::string folderText(const TestFile& f, const TestOptions& opt);

// The replay command of one failing run.
std::string replayCommand(const TestFile& f, const TestOptions& opt, const RunResult& r);

}  // namespace simswift::scenario_tests
