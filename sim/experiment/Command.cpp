#include "sim/experiment/Command.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "sim/experiment/Batch.hpp"
#include "sim/experiment/Trial.hpp"

namespace simswift::experiment {

const char* kExperimentUsage =
    "usage: simswift experiment FILE.yaml [--out DIR] [--jobs N] [--shard K/N] [--progress bar|lines|none]\n"
    "       simswift experiment FILE.yaml --check\n"
    "       simswift experiment merge DIR... --out DIR\n"
    "\n"
    "Runs a find-ball experiment (scenarios/thesis_findball.yaml, ...): every setup x ball\n"
    "position x trial, each trial in its own process, and writes into DIR (default\n"
    "results/<name>): results.csv, tracks.csv, report.md (the thesis's tables 5.3-5.12),\n"
    "figures/*.png, timing.md; with a sweep: in the file also cells.csv (one row per cell).\n"
    "Run the same command again to continue an interrupted run.\n"
    "\n"
    "  --out DIR          results folder\n"
    "  --jobs N           worker processes (default: the number of cores)\n"
    "  --shard K/N        run only trials K-1, K-1+N, K-1+2N, ... (K = 1..N); join the\n"
    "                     shard folders with `simswift experiment merge`\n"
    "  --progress MODE    bar (default on a terminal), lines (one per trial), none\n"
    "  --trial I          run only trial I, in this process, and print its results row\n"
    "                     (to debug or repeat one trial; its seed is in results.csv)\n"
    "  --check            validate the file (and that this build runs its behaviours), run nothing\n"
    "\n"
    "Exit codes: 0 done; 1 a trial or I/O failed, or another run is using the --out folder;\n"
    "2 bad command line or file (a folder of another experiment file included); 130 interrupted.\n";

namespace {

int usage(const std::string& msg) {
  std::fprintf(stderr, "simswift experiment: %s\n\n%s", msg.c_str(), kExperimentUsage);
  return 2;
}

bool parseInt(const std::string& s, int* v) {
  char* end = nullptr;
  const long x = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || x < 0 || x > 1000000) return false;
  *v = static_cast<int>(x);
  return true;
}

}  // namespace

int experimentMain(int argc, char** argv, const TrialHooks& hooks) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return usage("missing FILE.yaml or merge");
  if (args[0] == "--help" || args[0] == "-h") {
    std::printf("%s", kExperimentUsage);
    return 0;
  }
  const bool merge = args[0] == "merge";
  std::vector<std::string> positional;
  std::string out;
  BatchOptions opt;
  bool check = false;
  int single = -1;
  for (size_t i = merge ? 1 : 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const char* name) -> const std::string* {
      if (i + 1 >= args.size()) return nullptr;
      (void)name;
      return &args[++i];
    };
    if (a == "--help" || a == "-h") {
      std::printf("%s", kExperimentUsage);
      return 0;
    } else if (a == "--out") {
      const std::string* v = value("--out");
      if (!v || v->empty()) return usage("--out needs a folder");
      out = *v;
    } else if (!merge && a == "--jobs") {
      const std::string* v = value("--jobs");
      if (!v || !parseInt(*v, &opt.jobs) || opt.jobs < 1) return usage("--jobs: needs a whole number >= 1");
    } else if (!merge && a == "--shard") {
      const std::string* v = value("--shard");
      const size_t slash = v ? v->find('/') : std::string::npos;
      if (slash == std::string::npos || !parseInt(v->substr(0, slash), &opt.shard) ||
          !parseInt(v->substr(slash + 1), &opt.shards) || opt.shards < 1 || opt.shard < 1 || opt.shard > opt.shards)
        return usage("--shard: needs K/N with 1 <= K <= N (got '" + (v ? *v : std::string()) + "')");
    } else if (!merge && a == "--progress") {
      const std::string* v = value("--progress");
      if (v && *v == "bar") opt.progress = BatchOptions::Progress::Bar;
      else if (v && *v == "lines") opt.progress = BatchOptions::Progress::Lines;
      else if (v && *v == "none") opt.progress = BatchOptions::Progress::None;
      else return usage("--progress: bar, lines or none");
    } else if (!merge && a == "--trial") {
      const std::string* v = value("--trial");
      if (!v || !parseInt(*v, &single)) return usage("--trial: needs a trial number >= 0");
    } else if (!merge && a == "--check") {
      check = true;
    } else if (!a.empty() && a[0] == '-') {
      return usage("unknown option '" + a + "'");
    } else {
      positional.push_back(a);
    }
  }

  try {
    if (merge) {
      if (positional.empty()) return usage("merge: give the shard folders");
      if (out.empty()) return usage("merge: give the merged folder with --out DIR");
      const BatchOutcome o = mergeRuns(positional, out);
      std::fprintf(stderr, "%s\n", o.message.c_str());
      return o.assembled ? 0 : 1;
    }
    if (positional.size() != 1) return usage(positional.empty() ? "missing FILE.yaml" : "more than one FILE.yaml");
    const Experiment e = Experiment::loadFile(positional[0]);
    checkBehaviours(e, hooks);
    if (check) {
      const std::string cells = e.swept() ? std::to_string(e.numCells()) + " cells x " : "";
      std::printf("%s: ok: %d trials (%s%zu setups x %zu positions x %d)\n", positional[0].c_str(), e.numTrials(),
                  cells.c_str(), e.setups.size(), e.balls.size(), e.trials_per_position);
      return 0;
    }
    opt.out_dir = !out.empty() ? out
                  : opt.shards == 1 ? "results/" + e.name
                                    : "results/" + e.name + "-shard" + std::to_string(opt.shard) + "of" +
                                          std::to_string(opt.shards);
    if (single >= 0) {
      const TrialResult r = parseCsvRow(runSingleTrial(e, hooks, single, opt.out_dir), static_cast<int>(e.sweep.size()));
      std::printf("%s%s", csvHeader(e.maxRobots(), e.sweep).c_str(), csvRow(r, e.maxRobots()).c_str());
      return 0;
    }
    const BatchOutcome o = runBatch(e, hooks, opt);
    std::fprintf(stderr, "%s\n", o.message.c_str());
    if (o.interrupted) return 130;
    return o.failed ? 1 : 0;
  } catch (const ConfigError& ex) {
    std::fprintf(stderr, "simswift: %s\n", ex.what());
    return 2;
  } catch (const BatchInputError& ex) {  // a folder of another experiment: bad input too
    std::fprintf(stderr, "simswift: %s\n", ex.what());
    return 2;
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "simswift: %s\n", ex.what());
    return 1;
  }
}

}  // namespace simswift::experiment
