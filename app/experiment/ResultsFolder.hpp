// The results folder of a batch (layout: Batch.hpp): whose it is, which
// trials are done, which trial files it holds. trialFile() names them
// (declared in Batch.hpp, which tests use).
#pragma once

#include <string>
#include <vector>

#include "app/experiment/Experiment.hpp"
#include "common/lock/PidLock.hpp"

namespace simswift::experiment {

// Exclusive use of a results folder while it lives: an flock on dir/.lock
// (the file holds the holder's pid, for the message of a refused run). The
// batch's forked workers inherit it, so the folder stays locked until the
// last of them has ended (a worker outliving its batch included); launched
// robot programs do not (close-on-exec).
class FolderLock {
 public:
  FolderLock() = default;
  // Throws BatchError naming the folder and the holder's pid when another
  // process holds it. A holder whose run has ended (its pid is gone) but
  // whose workers are still ending is waited for, up to kWorkerEndWait_s.
  explicit FolderLock(const std::string& dir);

  // s: how long a refused run waits for a dead run's workers to end. They
  // get SIGKILL from the kernel when their batch dies (PR_SET_PDEATHSIG):
  // gone in milliseconds unless the machine is swamped.
  static constexpr double kWorkerEndWait_s = 5.0;

 private:
  common::lock::PidLock lock_;  // the flock and the pid: common/lock/PidLock.hpp
};

// Creates dir/trials, locks the folder (FolderLock) and claims it for `e`:
// its text is written once to dir/experiment.yaml, then must match
// (BatchInputError naming the folder and the first differing line if not).
// Removes temporary files of writers that died mid-write. Keep the lock
// for as long as the folder is written.
[[nodiscard]] FolderLock claimFolder(const Experiment& e, const std::string& dir);
// The same for any batch: `text` (read from `source`) is kept as
// dir/`copy_name` ("experiment.yaml", "tests.yaml").
[[nodiscard]] FolderLock claimFolder(const std::string& text, const std::string& source, const std::string& dir,
                                     const std::string& copy_name);

// A trial is done once its results row (trial_NNNNNN.csv, written last) is there.
bool trialDone(const std::string& dir, int trial);

// The trial files in a trials/ folder, sorted: no temporary files, no logs.
std::vector<std::string> listTrialFiles(const std::string& trials_dir);

}  // namespace simswift::experiment
