#include "sim/scenario_tests/TestCommand.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "agent/config/Seed.hpp"
#include "sim/experiment/BatchError.hpp"
#include "sim/scenario_tests/TestBatch.hpp"
#include "sim/world/ConfigError.hpp"

namespace simswift::scenario_tests {

const char* kTestUsage =
    "usage: simswift test FILE.yaml [--short] [--only A,B] [--out DIR] [--jobs N] [--shard K/N] [--seed N]\n"
    "                               [--baseline DIR] [--alpha A] [--junit FILE] [--progress lines|none]\n"
    "       simswift test FILE.yaml --check [--short] [--seed N]\n"
    "       simswift test FILE.yaml --test NAME --trial I [--seed N] [--overview DIR]\n"
    "       simswift test FILE.yaml --merge DIR... --out DIR [--short] [--seed N] [--baseline DIR] [--junit FILE]\n"
    "\n"
    "Runs a file of scenario tests (scenarios/tests/reference.yaml, docs/testing.md): every test's\n"
    "runs, each with its own seed and fuzzed start, each in its own process; then per test the\n"
    "pass count, its Wilson 95 % interval and the verdict against the required rate (passes,\n"
    "fails, or undecided: run more seeds), the failing seeds with their replay commands, and\n"
    "with --baseline whether a test regressed beyond chance. Writes into DIR (default\n"
    "results/tests-<name>[-short]): results.csv, summary.csv, report.md, pass_rates.png, junit.xml.\n"
    "Run the same command again to continue an interrupted run.\n"
    "\n"
    "  --short            the CI form: each test's short seed count\n"
    "  --only A,B,...     run only the tests named (in the file's order)\n"
    "  --out DIR          results folder\n"
    "  --jobs N           worker processes (default: the number of cores)\n"
    "  --shard K/N        run only runs K-1, K-1+N, ... (K = 1..N); join with --merge\n"
    "  --seed N           derive the runs' seeds from N instead of the file's seed\n"
    "  --baseline DIR     an earlier run's results folder (e.g. main's): call regressions\n"
    "  --alpha A          the regression call's family-wise level (default 0.05)\n"
    "  --junit FILE       also write the JUnit XML to FILE\n"
    "  --progress MODE    lines (default: one per run on stderr) or none\n"
    "  --test NAME --trial I   run test NAME's run I in this process and say how it went\n"
    "  --overview DIR     with --trial: whole-field overview PNGs of the run in DIR\n"
    "  --check            validate the file and every run's fuzzed placement; run nothing\n"
    "\n"
    "Exit codes: 0 every test passes and none regressed; 1 a test fails, is undecided or\n"
    "regressed, or a run could not run; 2 bad command line or file; 130 interrupted.\n";

namespace {

int usage(const std::string& msg) {
  std::fprintf(stderr, "simswift test: %s\n\n%s", msg.c_str(), kTestUsage);
  return 2;
}

// A whole number up to max, digits only (the seed reader's rules).
bool parseUnsigned(const std::string& s, uint64_t max, uint64_t* v) {
  const std::optional<uint64_t> x = agent::config::parseSeed(s);
  if (!x || *x > max) return false;
  *v = *x;
  return true;
}

}  // namespace

int testMain(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string file, test_name, overview, only;
  std::vector<std::string> merge_dirs;
  TestOptions opt;
  bool check = false, merge = false;
  int64_t trial = -1;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string* { return i + 1 < args.size() ? &args[++i] : nullptr; };
    uint64_t n = 0;
    if (a == "--help" || a == "-h") {
      std::printf("%s", kTestUsage);
      return 0;
    } else if (a == "--short") {
      opt.short_form = true;
    } else if (a == "--check") {
      check = true;
    } else if (a == "--out" || a == "--baseline" || a == "--junit" || a == "--test" || a == "--overview" ||
               a == "--only") {
      const std::string* v = value();
      if (!v || v->empty()) return usage(a + " needs a value");
      (a == "--out" ? opt.out_dir : a == "--baseline" ? opt.baseline : a == "--junit" ? opt.junit
                                    : a == "--test" ? test_name : a == "--only" ? only : overview) = *v;
    } else if (a == "--jobs") {
      const std::string* v = value();
      if (!v || !parseUnsigned(*v, 4096, &n) || n == 0) return usage("--jobs needs a number of workers (1..4096)");
      opt.jobs = static_cast<int>(n);
    } else if (a == "--trial") {
      const std::string* v = value();
      if (!v || !parseUnsigned(*v, 1000000, &n)) return usage("--trial needs a run number (0, 1, ...)");
      trial = static_cast<int64_t>(n);
    } else if (a == "--seed") {
      const std::string* v = value();
      const std::optional<uint64_t> s = v ? agent::config::parseSeed(*v) : std::nullopt;
      if (!s) return usage(std::string("--seed needs ") + agent::config::kSeedRange);
      opt.seed = *s;
      opt.has_seed = true;
    } else if (a == "--alpha") {
      const std::string* v = value();
      char* end = nullptr;
      const double x = v ? std::strtod(v->c_str(), &end) : 0;
      if (!v || *end != '\0' || !(x > 0 && x < 1)) return usage("--alpha needs a level in (0, 1)");
      opt.alpha = x;
    } else if (a == "--shard") {
      const std::string* v = value();
      const size_t slash = v ? v->find('/') : std::string::npos;
      uint64_t k = 0, m = 0;
      if (slash == std::string::npos || !parseUnsigned(v->substr(0, slash), 100000, &k) ||
          !parseUnsigned(v->substr(slash + 1), 100000, &m) || k < 1 || m < 1 || k > m)
        return usage("--shard needs K/N with 1 <= K <= N");
      opt.shard = static_cast<int>(k);
      opt.shards = static_cast<int>(m);
    } else if (a == "--progress") {
      const std::string* v = value();
      if (!v || (*v != "lines" && *v != "none")) return usage("--progress needs lines or none");
      opt.progress_lines = *v == "lines";
    } else if (a == "--merge") {
      merge = true;
      while (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) merge_dirs.push_back(args[++i]);
      if (merge_dirs.empty()) return usage("--merge needs the shard folders");
    } else if (!a.empty() && a[0] == '-') {
      return usage("unknown option " + a);
    } else if (file.empty()) {
      file = a;
    } else {
      return usage("one test file only (got " + file + " and " + a + ")");
    }
  }
  if (file.empty()) return usage("missing FILE.yaml");
  if ((trial >= 0) != !test_name.empty()) return usage("--test and --trial go together");
  if (!overview.empty() && trial < 0) return usage("--overview goes with --test NAME --trial I");
  if (merge && opt.out_dir.empty()) return usage("--merge needs --out DIR");
  try {
    TestFile f = TestFile::loadFile(file);
    if (!only.empty()) {
      std::string err;
      if (!selectTests(f, only, &err)) return usage("--only: " + err);
      opt.only = only;
    }
    if (opt.out_dir.empty()) opt.out_dir = "results/tests-" + f.name + (opt.short_form ? "-short" : "");
    if (check) {
      checkPlacements(f, opt.short_form, opt.seed, opt.has_seed);
      std::printf("%s: %zu tests, %d runs (%s form): valid\n", file.c_str(), f.tests.size(),
                  countRuns(f, opt.short_form), opt.short_form ? "short" : "full");
      return 0;
    }
    if (trial >= 0) {
      int k = -1;
      for (size_t t = 0; t < f.tests.size(); ++t)
        if (f.tests[t].name == test_name) k = static_cast<int>(t);
      if (k < 0) return usage("no test named " + test_name + " in " + file);
      RunSpec s;
      s.test = k;
      s.run = static_cast<int>(trial);
      s.seed = runSeed(opt.has_seed ? opt.seed : f.seed, test_name, s.run);
      const RunResult r = runTest(f, s, "", overview);
      std::printf("%s run %d (seed %llu): %s at %.2f s%s%s (falls %d; %.1f simulated s in %.1f s of wall time)\n",
                  r.test.c_str(), r.run, static_cast<unsigned long long>(r.seed), r.passed ? "passed" : "failed",
                  r.passed ? r.decided_s : r.failure_s, r.passed ? "" : ": ", r.failure.c_str(), r.falls, r.sim_s,
                  r.wall_s);
      return r.passed ? 0 : 1;
    }
    const TestOutcome out = merge ? mergeTests(f, merge_dirs, opt) : runTests(f, opt);
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
