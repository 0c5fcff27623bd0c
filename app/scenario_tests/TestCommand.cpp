#include "app/scenario_tests/TestCommand.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "app/cli/CommandLine.hpp"
#include "app/experiment/BatchError.hpp"
#include "app/scenario_tests/TestRun.hpp"
#include "sim/world/ConfigError.hpp"

namespace simswift::scenario_tests {

namespace {

constexpr int kMaxJobs = 4096;
constexpr int kMaxShards = 100000;
constexpr int kMaxRun = 1000000;  // --trial

}  // namespace

TestCommand::TestCommand(CLI::App& parent) {
  cmd_ = parent.add_subcommand("test", "run a file of scenario tests (a team's CI)");
  cmd_->footer(
      "Other forms:\n"
      "  simswift test FILE.yaml --check [--short] [--seed N]\n"
      "  simswift test FILE.yaml --test NAME --trial I [--seed N] [--overview DIR]\n"
      "  simswift test FILE.yaml --merge DIR... --out DIR [--short] [--seed N] [--baseline DIR] [--junit FILE]\n"
      "\n"
      "Runs a file of scenario tests (scenarios/tests/reference.yaml, docs/testing.md): every test's\n"
      "runs, each with its own seed and fuzzed start, each in its own process; then per test the\n"
      "pass count, its Wilson 95 % interval and the verdict against the required rate (passes,\n"
      "fails, or undecided: run more seeds), the failing seeds with their replay commands, and\n"
      "with --baseline whether a test regressed beyond chance. Writes into DIR (default\n"
      "results/tests-<name>[-short]): results.csv, summary.csv, report.md, pass_rates.png, junit.xml.\n"
      "Run the same command again to continue an interrupted run.\n"
      "\n"
      "Exit codes: 0 every test passes and none regressed; 1 a test fails, is undecided or\n"
      "regressed, or a run could not run; 2 bad command line or file; 130 interrupted.");
  cmd_->add_option("FILE", file_, "the test file (FILE.yaml)")->type_name("")->required();
  cmd_->add_flag("--short", opt_.short_form, "the CI form: each test's short seed count");
  cmd_->add_option("--only", opt_.only, "run only the tests named (in the file's order)")
      ->type_name("A,B,...")
      ->transform(cli::nonEmpty());
  CLI::Option* out =
      cmd_->add_option("--out", opt_.out_dir, "results folder")->type_name("DIR")->transform(cli::nonEmpty());
  cmd_->add_option("--jobs", opt_.jobs, "worker processes (default: the number of cores)")
      ->type_name("N")
      ->transform(cli::wholeNumber(1, kMaxJobs));
  cmd_->add_option("--shard", shard_, "run only runs K-1, K-1+N, ... (K = 1..N); join with --merge")
      ->type_name("K/N")
      ->transform(cli::shard(kMaxShards));
  cmd_->add_option("--seed", seed_, "derive the runs' seeds from N instead of the file's seed")
      ->type_name("N")
      ->transform(cli::seed());
  cmd_->add_option("--baseline", opt_.baseline, "an earlier run's results folder (e.g. main's): call regressions")
      ->type_name("DIR")
      ->transform(cli::nonEmpty());
  cmd_->add_option("--alpha", opt_.alpha, "the regression call's family-wise level (default 0.05)")
      ->type_name("A")
      ->transform(CLI::Validator(
          [](std::string& text) -> std::string {
            const std::optional<double> a = cli::parseNumber(text);
            if (!a || !(*a > 0 && *a < 1)) return "must be a level in (0, 1) (got '" + text + "')";
            return cli::number()(text);  // rewritten exactly for CLI11's conversion
          },
          "", ""));
  cmd_->add_option("--junit", opt_.junit, "also write the JUnit XML to FILE")
      ->type_name("FILE")
      ->transform(cli::nonEmpty());
  cmd_->add_option("--progress", progress_, "lines (default: one per run on stderr) or none")
      ->type_name("MODE")
      ->transform(cli::oneOf({"lines", "none"}));
  CLI::Option* test = cmd_->add_option("--test", test_name_, "with --trial I: run test NAME's run I in this process\n"
                                                             "and say how it went")
                          ->type_name("NAME")
                          ->transform(cli::nonEmpty());
  CLI::Option* trial = cmd_->add_option("--trial", trial_, "with --test NAME: the run")
                           ->type_name("I")
                           ->transform(cli::wholeNumber(0, kMaxRun));
  test->needs(trial);
  trial->needs(test);
  cmd_->add_option("--overview", overview_, "with --trial: whole-field overview PNGs of the run in DIR")
      ->type_name("DIR")
      ->transform(cli::nonEmpty())
      ->needs(trial);
  cmd_->add_option("--record", record_,
                   "record runs as MCAP in DIR/recordings/ (docs/recording.md): failures keeps\n"
                   "the failing runs' recordings, all every run's (named in the report)")
      ->type_name("failures|all")
      ->transform(cli::oneOf({"failures", "all"}));
  cmd_->add_flag("--check", check_, "validate the file and every run's fuzzed placement; run nothing");
  cmd_->add_option("--merge", merge_dirs_, "join shard folders (--shard K/N runs) into --out DIR")
      ->type_name("DIR")
      ->needs(out);
}

bool TestCommand::chosen() const { return cmd_->parsed(); }

int TestCommand::run() const {
  TestOptions opt = opt_;
  if (const std::optional<cli::Shard> s = cli::parseShard(shard_, kMaxShards)) {
    opt.shard = s->k;
    opt.shards = s->n;
  }
  if (!progress_.empty()) opt.progress_lines = progress_ == "lines";
  if (!record_.empty()) opt.record = record_ == "all" ? TestOptions::Record::All : TestOptions::Record::Failures;
  if (seed_) {
    opt.seed = *seed_;
    opt.has_seed = true;
  }
  try {
    TestFile f = TestFile::loadFile(file_);
    if (!opt.only.empty()) {
      std::string err;
      if (!selectTests(f, opt.only, &err)) return cli::usageError(*cmd_, "--only: " + err);
    }
    if (opt.out_dir.empty()) opt.out_dir = "results/tests-" + f.name + (opt.short_form ? "-short" : "");
    if (check_) {
      checkPlacements(f, opt.short_form, opt.seed, opt.has_seed);
      std::printf("%s: %zu tests, %d runs (%s form): valid\n", file_.c_str(), f.tests.size(),
                  countRuns(f, opt.short_form), opt.short_form ? "short" : "full");
      return 0;
    }
    if (trial_) {
      int k = -1;
      for (size_t t = 0; t < f.tests.size(); ++t)
        if (f.tests[t].name == test_name_) k = static_cast<int>(t);
      if (k < 0) return cli::usageError(*cmd_, "--test: no test named " + test_name_ + " in " + file_);
      RunSpec s;
      s.test = k;
      s.run = *trial_;
      s.seed = runSeed(opt.has_seed ? opt.seed : f.seed, test_name_, s.run);
      RunResult probe;
      probe.test = test_name_;
      probe.run = s.run;
      const std::string rec = opt.record == TestOptions::Record::None ? "" : recordingPath(opt, probe);
      const RunResult r = runTest(f, s, "", overview_, rec);
      if (!rec.empty()) std::printf("recording %s\n", rec.c_str());
      std::printf("%s run %d (seed %llu): %s at %.2f s%s%s (falls %d; %.1f simulated s in %.1f s of wall time)\n",
                  r.test.c_str(), r.run, static_cast<unsigned long long>(r.seed), r.passed ? "passed" : "failed",
                  r.passed ? r.decided_s : r.failure_s, r.passed ? "" : ": ", r.failure.c_str(), r.falls, r.sim_s,
                  r.wall_s);
      return r.passed ? 0 : 1;
    }
    const TestOutcome out = merge_dirs_.empty() ? runTests(f, opt) : mergeTests(f, merge_dirs_, opt);
    if (out.assembled) std::printf("%s\n", out.message.c_str());
    else std::fprintf(stderr, "simswift test: %s\n", out.message.c_str());
    return out.exit_code;
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const experiment::BatchInputError& e) {
    std::fprintf(stderr, "simswift test: %s\n", e.what());
    return 2;
  } catch (const experiment::BatchError& e) {
    std::fprintf(stderr, "simswift test: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simswift test: %s\n", e.what());
    return 1;
  }
}

}  // namespace simswift::scenario_tests
