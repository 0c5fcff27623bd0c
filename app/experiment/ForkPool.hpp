// Trials in forked worker processes, whatever a trial is (a find-ball
// trial: WorkerPool.cpp; a scenario test's seed: app/scenario_tests). Each
// trial runs in a process of its own, at most `jobs` at a time, so a trial
// that crashes or hangs takes only itself down and its memory is returned
// when it ends. A worker's messages go to the job's log file for the trial,
// which is removed when the trial succeeds; the worker reports by the files
// it leaves, which the parent reads back (ForkJob::finished).
//
// Ctrl-C / SIGTERM: no further trial is launched, running ones end (they
// get the terminal's SIGINT too; a signal to the parent alone is passed
// on, as SIGTERM, at once), every finished trial is kept. The pool keeps
// SIGINT, SIGTERM and SIGCHLD blocked while it runs and takes them with
// sigwaitinfo, so a stop is never missed between a check and the wait. kill -9 of the parent alone: the
// kernel kills every worker (PR_SET_PDEATHSIG) and so the robot programs
// it launched (theirs, ProgramProcess.cpp); none runs on beside a resume.
#pragma once

#include <string>
#include <vector>

namespace simswift::experiment {

class ForkJob {
 public:
  virtual ~ForkJob() = default;
  // The worker's stdout and stderr (kept only if the trial fails).
  virtual std::string logFile(int trial) const = 0;
  // In the worker process: runs the trial and writes its files. A
  // ConfigError ends the worker with code 2, any other exception with 1.
  virtual void run(int trial) const = 0;
  // In the parent: whether the trial's files say it is done.
  virtual bool done(int trial) const = 0;
  // In the parent: a trial ended well (done); `peak_mb` its process's peak
  // resident memory (MB).
  virtual void finished(int trial, double peak_mb) = 0;
  // In the parent: a trial's process failed; `why` ends with its log's tail.
  virtual void failed(int trial, const std::string& why) = 0;
  // In the parent: called each time the pool, having checked for a stop and
  // launched what it may, is about to wait for a worker or a signal. Does
  // nothing; tests deliver a signal here, the moment a stop could be missed.
  virtual void waiting() {}
};

struct ForkRun {
  int ran = 0;     // trials finished
  int failed = 0;  // trials whose process failed (logs kept)
  bool interrupted = false;
  double wall_s = 0;  // s, from the first launch to the last trial's end
  double peak_mb = 0; // MB: the largest peak resident memory of one trial process
};

// Runs `todo` with at most `jobs` workers; with private_shm each worker
// first enters its own /dev/shm (PrivateShm.hpp). Throws BatchError when
// fork or wait fails.
ForkRun runForked(ForkJob& job, const std::vector<int>& todo, int jobs, bool private_shm);

}  // namespace simswift::experiment
