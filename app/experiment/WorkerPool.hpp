// Find-ball trials in worker processes (ForkPool.hpp): each trial is forked into a process of its
// own, at most `jobs` at a time, so a trial that crashes or hangs takes
// only itself down and its memory is returned when it ends. A worker runs
// runAndWriteTrial, its messages going to trial_NNNNNN.log (kept only if it
// fails), and reports by the files it leaves: the parent reads the trial's
// results row and timing row back (parseCsvRow, parseTimingRow) for the
// progress line and the wall clock.
//
// Ctrl-C / SIGTERM: no further trial is launched, running ones end (they
// get the terminal's SIGINT too; a signal to the parent alone is passed
// on), every finished trial is kept. kill -9 of the parent alone: the
// kernel kills every worker (PR_SET_PDEATHSIG) and so the robot programs
// it launched (theirs, ProgramProcess.cpp); none runs on beside a resume.
#pragma once

#include <string>
#include <vector>

#include "app/experiment/Experiment.hpp"
#include "app/experiment/ProgressLine.hpp"
#include "app/experiment/Report.hpp"
#include "app/experiment/TrialHooks.hpp"

namespace simswift::experiment {

struct WorkerRun {
  int ran = 0;     // trials finished
  int failed = 0;  // trials whose process failed (logs kept)
  bool interrupted = false;
};

// Runs trials `todo` of `e` into folder `dir` with at most `jobs` workers;
// with private_shm each worker first enters its own /dev/shm
// (PrivateShm.hpp). Adds the trials' wall clock to `wall` (ran, simulated
// and worker seconds, peak memory, wall_s from the first launch).
WorkerRun runWorkers(const Experiment& e, const TrialHooks& hooks, const std::string& dir, const std::vector<int>& todo,
                     int jobs, bool private_shm, ProgressLine& progress, RunWall& wall);

}  // namespace simswift::experiment
