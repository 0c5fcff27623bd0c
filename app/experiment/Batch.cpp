#include "app/experiment/Batch.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include <sys/resource.h>
#include <unistd.h>

#include "app/experiment/Files.hpp"
#include "app/experiment/PrivateShm.hpp"
#include "app/experiment/ProgressLine.hpp"
#include "app/experiment/ResultsFolder.hpp"
#include "app/experiment/Trial.hpp"
#include "app/experiment/WorkerPool.hpp"

namespace simswift::experiment {

namespace {

// Launched robot programs open their release's fixed names: each worker
// gets its own /dev/shm (PrivateShm.hpp), or the trials run one at a time
// (*jobs becomes 1, said on stderr). Returns whether workers take a private /dev/shm.
bool privateShmFor(const Experiment& e, int* jobs) {
  bool launches = false;
  for (const Setup& s : e.setups)
    for (const ExperimentRobot& r : s.robots) launches = launches || r.launch.launched();
  if (!launches) return false;
  std::string why;
  const bool private_shm = privateShmAvailable(&why);
  if (!private_shm && *jobs > 1) {
    std::fprintf(stderr,
                 "simswift: this machine gives no private /dev/shm to a trial (%s); launched robot programs "
                 "share names, so the trials run one at a time\n",
                 why.c_str());
    *jobs = 1;
  }
  return private_shm;
}

// What runBatch tells the user at the end; assembles the folder when its
// last trial is in (a rerun in a finished folder changes nothing: the
// report keeps the wall clock of the run that finished it).
std::string endOfBatch(const Experiment& e, const BatchOptions& opt, BatchOutcome& out, const RunWall& wall, int jobs) {
  const int done = out.already + out.ran;
  std::ostringstream m;
  if (out.interrupted) {
    m << "interrupted: " << done << " of " << out.trials
      << " trials kept in " << opt.out_dir << "; run the same command again to continue";
  } else if (out.failed) {
    m << out.failed << " trial(s) failed (logs in " << opt.out_dir << "/trials); rerun to retry them";
  } else {
    bool all = true;
    for (int t = 0; t < e.numTrials() && all; ++t) all = trialDone(opt.out_dir, t);
    if (all) {
      std::string notes;
      if (wall.ran > 0 || !exists(opt.out_dir + "/report.md")) assemble(e, opt.out_dir, &notes, &wall);
      out.assembled = true;
      m << notes;
      if (wall.ran > 0)
        m << "ran " << wall.ran << " trial(s) with " << jobs << " worker(s) in " << formatDuration(wall.wall_s)
          << " of wall time (" << fixed(wall.wall_s > 0 ? wall.trial_sim_s / wall.wall_s : 0, 1)
          << " simulated s per wall s; peak memory of one trial process " << fixed(wall.peak_trial_mb, 0)
          << " MB)\n";
      m << "report: " << opt.out_dir << "/report.md (also results.csv, tracks.csv, figures/, timing.md)";
    } else {
      m << "shard " << opt.shard << "/" << opt.shards << ": " << done << " trials in " << opt.out_dir
        << "; join the shards with `simswift experiment merge DIR... --out DIR`";
    }
  }
  return m.str();
}

}  // namespace

void runAndWriteTrial(const Experiment& e, const TrialHooks& hooks, int trial, const std::string& dir) {
  // Launched programs' logs and setups: dir/trials/<trial>/.
  const std::string rec = hooks.record.count(trial) ? dir + "/recordings/trial_" + std::to_string(trial) + ".mcap" : "";
  TrialResult r = runTrial(e, trial, hooks, dir + "/trials/" + std::to_string(trial), rec);
  // This process's peak resident memory: the trial's worker (ru_maxrss is in
  // KiB on Linux; launched robot programs are processes of their own).
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) == 0) r.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  writeAtomic(trialFile(dir, trial, ".tracks.csv"), tracksRows(r, e));
  writeAtomic(trialFile(dir, trial, ".timing.csv"), timingRow(r));
  writeAtomic(trialFile(dir, trial, ".csv"), csvRow(r, static_cast<int>(r.robots.size())));  // last: "done"
}

std::string runSingleTrial(const Experiment& e, const TrialHooks& hooks, int trial, const std::string& out_dir) {
  checkBehaviours(e, hooks);
  if (trial < 0 || trial >= e.numTrials())
    throw BatchError("--trial " + std::to_string(trial) + ": the experiment has trials 0.." +
                     std::to_string(e.numTrials() - 1));
  const FolderLock lock = claimFolder(e, out_dir);
  runAndWriteTrial(e, hooks, trial, out_dir);
  return readFile(trialFile(out_dir, trial, ".csv"));
}

BatchOutcome runBatch(const Experiment& e, const TrialHooks& hooks, const BatchOptions& opt) {
  checkBehaviours(e, hooks);  // before any trial: refuses what this build cannot run
  if (opt.shards < 1 || opt.shard < 1 || opt.shard > opt.shards) throw BatchError("bad shard");
  // Held to the end (and by the workers): no other run writes these trials meanwhile.
  const FolderLock lock = claimFolder(e, opt.out_dir);

  BatchOutcome out;
  std::vector<int> todo;
  for (int t = opt.shard - 1; t < e.numTrials(); t += opt.shards) {
    ++out.trials;
    if (trialDone(opt.out_dir, t)) ++out.already;
    else todo.push_back(t);
  }
  int jobs = opt.jobs > 0 ? opt.jobs : static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
  jobs = std::max(1, std::min<int>(jobs, static_cast<int>(todo.size())));

  ProgressLine progress;
  progress.total = out.trials;
  progress.done = out.already;
  const bool tty = isatty(STDERR_FILENO);
  progress.bar = opt.progress == BatchOptions::Progress::Bar || (opt.progress == BatchOptions::Progress::Auto && tty);
  progress.lines = opt.progress != BatchOptions::Progress::None;
  if (progress.lines && out.already > 0)
    std::fprintf(stderr, "%s: %d of %d trials already done, resuming\n", opt.out_dir.c_str(), out.already,
                 out.trials);

  std::fflush(stdout);  // nothing buffered to be written twice by the forked workers
  std::fflush(stderr);
  RunWall wall;
  wall.jobs = jobs;  // as asked: before privateShmFor may run the trials one at a time
  const bool private_shm = privateShmFor(e, &jobs);
  const WorkerRun run = runWorkers(e, hooks, opt.out_dir, todo, jobs, private_shm, progress, wall);
  out.ran = run.ran;
  out.failed = run.failed;
  out.interrupted = run.interrupted;
  out.message = endOfBatch(e, opt, out, wall, jobs);
  return out;
}

}  // namespace simswift::experiment
