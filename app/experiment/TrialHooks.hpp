// The two pluggable parts of a find-ball trial:
//
//  - BehaviourFactory: says which behaviours this build can run (refused at
//    validation, before any trial) and sets each robot up for a trial: its
//    behaviour and overrides. The start itself (penalised at the start
//    poses, then PLAYING) is the trial's (runTrial's stages 1-2, Trial.hpp).
//  - FoundRule: after every tick of play, which robot (if any) has found
//    the ball (the tick's stage 3, Trial.hpp).
//
// behaviourHooks() (BehaviourHooks.hpp): the agent/behaviour behaviours and
// the VisionFoundRule.
#pragma once

#include <memory>
#include <set>

#include "app/experiment/Experiment.hpp"
#include "sim/runner/Runner.hpp"

namespace simswift::experiment {

class BehaviourFactory {
 public:
  virtual ~BehaviourFactory() = default;
  // Throws ConfigError (naming r.behaviour_where) if this build cannot run
  // robot r's behaviour. Called for every robot before any trial runs.
  virtual void check(const Experiment& e, const ExperimentRobot& r) const = 0;
  // The trial's scenario: robots are placed and their scripts set
  // (trialScenario); set behaviours, overrides and the vision block here
  // (runTrial's stage 1, setUpTrial).
  virtual void configure(const Experiment& e, const TrialSpec& t, runner::Scenario& sc) const = 0;
  // Before Runner::start() (stage 2, startRunner): motion / perception
  // replacements, if any.
  virtual void attach(const Experiment& e, const TrialSpec& t, runner::Runner& r) const {}
  // After start(), before the first tick: penalised -> PLAYING, ball
  // knowledge cleared. Nothing to do for script robots.
  virtual void startPlay(const Experiment& e, const TrialSpec& t, runner::Runner& r) const {}
};

class FoundRule {
 public:
  virtual ~FoundRule() = default;
  // After each tick: the scenario index of a robot that has found the ball
  // (the lowest index if several), or -1.
  virtual int finder(const Experiment& e, runner::Runner& r) const = 0;
};

struct TrialHooks {
  std::shared_ptr<const BehaviourFactory> behaviours;
  std::shared_ptr<const FoundRule> found;
  // `--record I,J,...`: these trials recorded as MCAP (docs/recording.md)
  // into <out>/recordings/trial_<I>.mcap.
  std::set<int> record;
};

// Found by what the robot's vision reports (thesis §5.1: a robot "could both
// see the ball, and was within 300mm (inclusive)"): with `found.sees`, the
// vision oracle gave the robot the true ball (no false positive) in the
// latest found.seen_frames camera frames in a row -- the same detector model, range, occlusion, noise
// and draws its Perception got -- at a detected distance <= found.distance;
// without, the true ground distance from the point between its feet.
// Deterministic: the oracle's draws are seeded per (seed, robot, frame).
class VisionFoundRule : public FoundRule {
 public:
  int finder(const Experiment& e, runner::Runner& r) const override;
  // m, true ground distance from the point between robot's feet to the ball.
  static double ballDistance(runner::Runner& r, int robot);
};

// Validates every robot's behaviour against the hooks (throws ConfigError).
void checkBehaviours(const Experiment& e, const TrialHooks& hooks);

}  // namespace simswift::experiment
