// One find-ball trial: a pure function of (experiment, trial index).
//
// runTrial is a straight line of stages, in this order (Trial.cpp; this is
// the one place the order is written down). The trial passes through them
// as one value (Trial.cpp's TrialState: spec, scenario, runner, clock, the
// result row), each stage reading and writing parts of it:
//   1. setUpTrial       the trial's spec (setup, ball, repeat, seed, sweep
//                       cell) and scenario (trialScenario: robots at their
//                       start poses, the ball at its position, the seed, the
//                       game: penalised, then PLAYING), the BehaviourFactory's
//                       behaviours; the result's header (which trial, its robots)
//   2. startRunner      the Runner built and started (its t = 0 penalties
//                       take the robots to the sideline), the robots put back
//                       on their start poses, penalised
//   3. playUntilFound   ticks until the FoundRule names a finder or the time
//                       limit after PLAYING has run. Each tick, in this order:
//        1. Runner::tick() (robots, physics, sensors, vision, game: Runner.hpp)
//        2. the fallen-robot rule: a robot down (torso below kFallHeight,
//           until above kStandHeight) for `fallen.sideline_after` s is moved
//           to its nearest touch line, standing, facing the field
//        (until playTick nothing else: the robots are penalised; at the end
//        of playTick they are unpenalised, the trial's clock starts at 0 and
//        every robot's track starts)
//        3. the found rule
//        4. track samples every `tracks.every` s of play and at the trial's
//           last tick (found or the limit); walked distance is summed over
//           them, which also averages out the walk's sway
//   4. classifyOutcome  found or not; if found, when and by whom
//   5. recordRunStats   the runner's falls, contact falls, resets and
//                       simulated time; the runner shut down
//   6. the wall-clock time (timing only)
// A launched robot program that fails (runner::ProgramError) in 2-5 ends
// the trial there: its result is the header and the reason (`failed`).
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
// record_path: the trial recorded as MCAP there ("" = not recorded).
TrialResult runTrial(const Experiment& e, int index, const TrialHooks& hooks, const std::string& program_logs = "",
                     const std::string& record_path = "");

// Trial `index` through runTrial's stages 1-2: its scenario with the
// behaviour hooks, the robot programs inline, the robots on their start
// poses, penalised until playTick(e). The caller ticks it and watches what
// it likes (tools/findball_trace.cpp, tests); no found or sideline rule.
std::unique_ptr<runner::Runner> startTrial(const Experiment& e, int index, const TrialHooks& hooks);

}  // namespace simswift::experiment
