// One find-ball trial: a pure function of (experiment, trial index).
//
// runTrial builds the trial's scenario (robots at their start poses, the
// ball at its position, the trial's seed, the game: penalised, then
// PLAYING), lets the BehaviourFactory set behaviours up, starts the Runner
// (its t = 0 penalties take the robots to the sideline), puts the robots back
// on their start poses, penalised, and ticks until the FoundRule names a
// finder or the time limit after PLAYING passes. Each tick, in this order:
//   1. Runner::tick() (robots, physics, sensors, vision, game);
//   2. the fallen-robot rule: a robot down (torso below kFallHeight, until
//      above kStandHeight) for `fallen.sideline_after` s is moved to its
//      nearest touch line, standing, facing the field;
//   (until playTick nothing else: the robots are penalised; at playTick
//   they are unpenalised and the trial's clock starts at 0)
//   3. track sample every `tracks.every` s of play (walked distance is
//      summed over these samples, which also averages out the walk's sway);
//   4. the found rule.
// Find times and track times are s since PLAYING.
//
// The result and its rows in results.csv (deterministic), tracks.csv and
// timing.csv (wall clock: never part of the results): TrialResult.hpp.
#pragma once

#include <memory>
#include <string>

#include "app/experiment/Experiment.hpp"
#include "app/experiment/TrialHooks.hpp"
#include "app/experiment/TrialResult.hpp"

namespace simswift::experiment {

// Runs trial `index`. Launched robot programs (program: {command: ...})
// start fresh for the trial, their logs and setups in program_logs ("" =
// the experiment's default); if one fails the result says so in `failed`.
TrialResult runTrial(const Experiment& e, int index, const TrialHooks& hooks, const std::string& program_logs = "");

// Trial `index` set up as runTrial sets it up: its scenario with the
// behaviour hooks, the robot programs inline, the robots on their start
// poses, penalised until playTick(e). The caller ticks it and watches what
// it likes (tools/findball_trace.cpp, tests); no found or sideline rule.
std::unique_ptr<runner::Runner> startTrial(const Experiment& e, int index, const TrialHooks& hooks);

}  // namespace simswift::experiment
