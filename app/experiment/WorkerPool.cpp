#include "app/experiment/WorkerPool.hpp"

#include <algorithm>

#include "app/experiment/Batch.hpp"
#include "app/experiment/Files.hpp"
#include "app/experiment/ForkPool.hpp"
#include "app/experiment/ResultsFolder.hpp"

namespace simswift::experiment {

namespace {

// A find-ball trial as a ForkJob: the worker runs runAndWriteTrial; the
// parent reads a finished trial's results and timing rows back for the
// progress line and the wall clock.
class TrialJob : public ForkJob {
 public:
  TrialJob(const Experiment& e, const TrialHooks& hooks, const std::string& dir, ProgressLine& progress, RunWall& wall)
      : e_(e), hooks_(hooks), dir_(dir), progress_(progress), wall_(wall) {}

  std::string logFile(int t) const override { return trialFile(dir_, t, ".log"); }
  void run(int t) const override { runAndWriteTrial(e_, hooks_, t, dir_); }
  bool done(int t) const override { return trialDone(dir_, t); }
  void finished(int t, double peak_mb) override {
    TrialResult r = parseCsvRow(readFile(trialFile(dir_, t, ".csv")), static_cast<int>(e_.sweep.size()));
    parseTimingRow(readFile(trialFile(dir_, t, ".timing.csv")), r);
    progress_.trial(r);
    ++wall_.ran;
    wall_.trial_sim_s += r.sim_s;
    wall_.trial_wall_s += r.wall_s;
    wall_.peak_trial_mb = std::max(wall_.peak_trial_mb, peak_mb);
  }
  void failed(int t, const std::string& why) override { progress_.fail(t, why); }

 private:
  const Experiment& e_;
  const TrialHooks& hooks_;
  const std::string& dir_;
  ProgressLine& progress_;
  RunWall& wall_;
};

}  // namespace

WorkerRun runWorkers(const Experiment& e, const TrialHooks& hooks, const std::string& dir, const std::vector<int>& todo,
                     int jobs, bool private_shm, ProgressLine& progress, RunWall& wall) {
  TrialJob job(e, hooks, dir, progress, wall);
  const ForkRun f = runForked(job, todo, jobs, private_shm);
  progress.end();
  wall.wall_s = f.wall_s;
  wall.peak_trial_mb = std::max(wall.peak_trial_mb, f.peak_mb);
  return WorkerRun{f.ran, f.failed, f.interrupted};
}

}  // namespace simswift::experiment
