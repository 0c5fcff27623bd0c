// Running an experiment's trials as a batch: worker processes, shards,
// resume, merge and the assembled results folder.
//
// Results folder (one per run):
//   .lock                  flock of the run using the folder, and its pid (ResultsFolder.hpp)
//   experiment.yaml        the experiment file's text (a rerun must match it)
//   trials/trial_NNNNNN.csv          one results row, written last (temp + rename):
//   trials/trial_NNNNNN.tracks.csv   its presence means the trial is done
//   trials/trial_NNNNNN.timing.csv   wall clock (never part of the results)
//   trials/trial_NNNNNN.log          the trial's messages, kept only if it failed
//   results.csv, tracks.csv, report.md, figures/   once every trial is done
//   timing.csv, timing.md                          wall clock: real-time factors (also
//                                                  report.md's last section)
//
// Each trial runs in its own forked process, at most `jobs` at a time: a
// trial that crashes or hangs takes only itself down, and its memory is
// returned when it ends. (Worlds stepped one after another could share a
// process: World::step reseeds ODE's one random generator from its tick.)
// Everything but timing.* and report.md's wall-clock section is a pure
// function of the experiment file, so reruns, --jobs, shards + merge and
// interrupted-then-resumed runs give byte-identical results.
//
// The parts, one file each: ResultsFolder (claiming the folder, which
// trials are done), WorkerPool (the forked workers and Ctrl-C),
// ProgressLine (stderr), Merge.cpp (shards), Assemble.cpp (results.csv,
// tracks.csv, timing.csv, report.md), TimingPage (timing.md), FolderFigures
// (figures/), Files (atomic writes and the other file operations).
#pragma once

#include <string>
#include <vector>

#include "app/experiment/BatchError.hpp"
#include "app/experiment/Experiment.hpp"
#include "app/experiment/Report.hpp"
#include "app/experiment/TrialHooks.hpp"

namespace simswift::experiment {

struct BatchOptions {
  std::string out_dir;       // results folder (created)
  int jobs = 0;              // worker processes; 0 = the number of cores
  int shard = 1, shards = 1; // run trials with index % shards == shard - 1
  enum class Progress { Auto, Bar, Lines, None } progress = Progress::Auto;  // Auto: bar on a terminal
};

struct BatchOutcome {
  int trials = 0;        // in this shard
  int already = 0;       // done before this run (resume)
  int ran = 0;           // finished by this run
  int failed = 0;        // trials whose process failed (logs kept)
  bool interrupted = false;
  bool assembled = false;  // every trial of the experiment present: results written
  std::string message;     // what to tell the user at the end
};

// Throws ConfigError (behaviours), BatchInputError (a folder of another
// experiment) or BatchError (a folder another run is using, I/O).
BatchOutcome runBatch(const Experiment& e, const TrialHooks& hooks, const BatchOptions& opt);

// Joins shard folders (same experiment file) into `out`; assembles if every
// trial is present. Throws BatchError.
BatchOutcome mergeRuns(const std::vector<std::string>& dirs, const std::string& out);

// Writes results.csv, tracks.csv, timing.*, report.md and figures/ from
// dir/trials; `run` (may be null): the wall clock of the run that completed
// the folder, for the report's timing part. Throws BatchError if a trial is missing.
void assemble(const Experiment& e, const std::string& dir, std::string* notes, const RunWall* run = nullptr);

// Runs one trial in this process and writes its files into dir/trials
// (the worker's job; also used by tests).
void runAndWriteTrial(const Experiment& e, const TrialHooks& hooks, int trial, const std::string& dir);

// `simswift experiment FILE --trial I`: runs trial I in this process (to
// debug or repeat one trial), writes its files into out_dir/trials and
// returns its results row.
std::string runSingleTrial(const Experiment& e, const TrialHooks& hooks, int trial, const std::string& out_dir);

std::string trialFile(const std::string& dir, int trial, const std::string& suffix);  // dir/trials/trial_NNNNNN<suffix>

}  // namespace simswift::experiment
