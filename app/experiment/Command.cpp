#include "app/experiment/Command.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "app/cli/CommandLine.hpp"
#include "app/experiment/Trial.hpp"

namespace simswift::experiment {

namespace {

constexpr int kMaxCount = 1000000;  // --jobs, --trial and --shard's N

}  // namespace

ExperimentCommand::ExperimentCommand(CLI::App& parent) {
  cmd_ = parent.add_subcommand("experiment", "run a find-ball experiment, or merge its shard folders");
  cmd_->footer(
      "Runs a find-ball experiment (scenarios/thesis_findball.yaml, ...): every setup x ball\n"
      "position x trial, each trial in its own process, and writes into DIR (default\n"
      "results/<name>): results.csv, tracks.csv, report.md (the thesis's tables 5.3-5.12),\n"
      "figures/*.png, timing.md; with a sweep: in the file also cells.csv (one row per cell).\n"
      "Run the same command again to continue an interrupted run.\n"
      "\n"
      "Exit codes: 0 done; 1 a trial or I/O failed, or another run is using the --out folder;\n"
      "2 bad command line or file (a folder of another experiment file included); 130 interrupted.");
  std::vector<CLI::Option*> own;  // what `merge` does not take
  own.push_back(cmd_->add_option("FILE", file_, "the experiment file (FILE.yaml)")->type_name(""));
  own.push_back(cmd_->add_option("--out", out_, "results folder")->type_name("DIR")->transform(cli::nonEmpty()));
  own.push_back(cmd_->add_option("--jobs", opt_.jobs, "worker processes (default: the number of cores)")
                    ->type_name("N")
                    ->transform(cli::wholeNumber(1, kMaxCount)));
  own.push_back(cmd_->add_option("--shard", shard_,
                                 "run only trials K-1, K-1+N, K-1+2N, ... (K = 1..N); join the\n"
                                 "shard folders with `simswift experiment merge`")
                    ->type_name("K/N")
                    ->transform(cli::shard(kMaxCount)));
  own.push_back(cmd_->add_option("--progress", progress_, "bar (default on a terminal), lines (one per trial), none")
                    ->type_name("MODE")
                    ->transform(cli::oneOf({"bar", "lines", "none"})));
  own.push_back(cmd_->add_option("--trial", trial_,
                                 "run only trial I, in this process, and print its results row\n"
                                 "(to debug or repeat one trial; its seed is in results.csv)")
                    ->type_name("I")
                    ->transform(cli::wholeNumber(0, kMaxCount)));
  own.push_back(cmd_->add_option("--record", record_,
                                 "record these trials as MCAP in DIR/recordings/trial_<I>.mcap\n"
                                 "(docs/recording.md; `simswift view` replays them)")
                    ->type_name("I,J,...")
                    ->delimiter(',')
                    ->transform(cli::wholeNumber(0, kMaxCount)));
  own.push_back(
      cmd_->add_flag("--check", check_, "validate the file (and that this build runs its behaviours), run nothing"));

  merge_ = cmd_->add_subcommand("merge", "join shard folders (--shard K/N runs) into one results folder");
  merge_->add_option("DIR", merge_dirs_, "the shard folders")->type_name("")->required();
  merge_->add_option("--out", merge_out_, "the merged folder")->type_name("DIR")->required()->transform(cli::nonEmpty());
  for (CLI::Option* o : own) merge_->excludes(o);
}

bool ExperimentCommand::chosen() const { return cmd_->parsed(); }

int ExperimentCommand::run(const TrialHooks& given) const {
  TrialHooks hooks = given;
  hooks.record.insert(record_.begin(), record_.end());
  try {
    if (merge_->parsed()) {
      const BatchOutcome o = mergeRuns(merge_dirs_, merge_out_);
      std::fprintf(stderr, "%s\n", o.message.c_str());
      return o.assembled ? 0 : 1;
    }
    if (file_.empty()) return cli::usageError(*cmd_, "missing FILE.yaml (or merge)");
    BatchOptions opt = opt_;
    if (const std::optional<cli::Shard> s = cli::parseShard(shard_, kMaxCount)) {
      opt.shard = s->k;
      opt.shards = s->n;
    }
    if (progress_ == "bar") opt.progress = BatchOptions::Progress::Bar;
    if (progress_ == "lines") opt.progress = BatchOptions::Progress::Lines;
    if (progress_ == "none") opt.progress = BatchOptions::Progress::None;
    const Experiment e = Experiment::loadFile(file_);
    checkBehaviours(e, hooks);
    if (check_) {
      const std::string cells = e.swept() ? std::to_string(e.numCells()) + " cells x " : "";
      std::printf("%s: ok: %d trials (%s%zu setups x %zu positions x %d)\n", file_.c_str(), e.numTrials(),
                  cells.c_str(), e.setups.size(), e.balls.size(), e.trials_per_position);
      return 0;
    }
    opt.out_dir = !out_.empty() ? out_
                  : opt.shards == 1 ? "results/" + e.name
                                    : "results/" + e.name + "-shard" + std::to_string(opt.shard) + "of" +
                                          std::to_string(opt.shards);
    for (const int t : record_)
      if (t >= e.numTrials())
        return cli::usageError(*cmd_, "--record: no trial " + std::to_string(t) + " (the experiment has trials 0.." +
                                          std::to_string(e.numTrials() - 1) + ")");
    if (trial_) {
      const TrialResult r =
          parseCsvRow(runSingleTrial(e, hooks, *trial_, opt.out_dir), static_cast<int>(e.sweep.size()));
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
