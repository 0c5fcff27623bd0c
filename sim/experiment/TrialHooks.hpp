// The two pluggable parts of a find-ball trial:
//
//  - BehaviourFactory: says which behaviours this build can run (refused at
//    validation, before any trial) and sets each robot up for a trial: its
//    behaviour and overrides, the vision block, and -- once the robots run
//    game states -- penalised at placement, ball knowledge cleared, then
//    PLAYING (findballexp's sequence, thesis §3.2.6).
//  - FoundRule: after every tick, which robot (if any) has found the ball.
//
// defaultHooks() is what this build has: script robots only, and a found
// rule computed from ground truth. When the behaviours (issue 12) and the
// vision oracle (issue 11) land, the lead plugs them in here: a factory that
// maps findball2016/findball2017/striker to the scenario's behaviour: field
// and passes Experiment::vision_yaml and the robot's config_yaml through,
// and a FoundRule using the oracle's "seen". A sketch (field names are
// whatever those issues call them):
//
//   struct BehaviourHooks : BehaviourFactory {
//     void check(const Experiment&, const ExperimentRobot&) const override {}  // all built
//     void configure(const Experiment& e, const TrialSpec& t, runner::Scenario& sc) const override {
//       const Setup& s = e.setups[t.setup];
//       for (size_t i = 0; i < s.robots.size(); ++i) {
//         if (s.robots[i].behaviour == Behaviour::Script) continue;       // actions already set
//         sc.robots[i].behaviour = behaviourName(s.robots[i].behaviour);  // scenario behaviour:
//         sc.robots[i].behaviour_overrides = s.robots[i].config_yaml;     // its config overrides
//       }
//       sc.vision = e.vision_yaml;                                        // scenario vision:
//     }
//     void startPlay(...) const override { /* penalise, clear ball knowledge, PLAYING */ }
//   };
//   // app/simswift.cpp:
//   experimentMain(argc - 1, argv + 1, {std::make_shared<BehaviourHooks>(),
//                                       std::make_shared<OracleFoundRule>()});
#pragma once

#include <memory>

#include "sim/experiment/Experiment.hpp"
#include "sim/runner/Runner.hpp"

namespace simswift::experiment {

class BehaviourFactory {
 public:
  virtual ~BehaviourFactory() = default;
  // Throws ConfigError (naming r.behaviour_where) if this build cannot run
  // robot r's behaviour. Called for every robot before any trial runs.
  virtual void check(const Experiment& e, const ExperimentRobot& r) const = 0;
  // The trial's scenario: robots are placed and their scripts set
  // (trialScenario); set behaviours, overrides and the vision block here.
  virtual void configure(const Experiment& e, const TrialSpec& t, runner::Scenario& sc) const = 0;
  // Before Runner::start(): motion / perception replacements, if any.
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
};

// Script robots run their actions: list; findball2016, findball2017 and
// striker are refused ("not built yet in this simswift").
class ScriptBehaviours : public BehaviourFactory {
 public:
  void check(const Experiment& e, const ExperimentRobot& r) const override;
  void configure(const Experiment& e, const TrialSpec& t, runner::Scenario& sc) const override;
};

// Found from ground truth: the ball centre within `found.distance` of the
// robot (torso, on the ground; inclusive) and, if `found.sees`, projecting
// into the top or bottom camera's image (60.9 x 47.6 deg, from the true head
// pose; occlusion is not checked). TODO(issue 11): replace "in a camera's
// view" by the vision oracle's "seen" (detection range, occlusion, noise).
class GroundTruthFoundRule : public FoundRule {
 public:
  int finder(const Experiment& e, runner::Runner& r) const override;
  // The geometric test alone, for one robot of a world.
  static bool ballInView(const World& w, int robot);
  static double ballDistance(const World& w, int robot);  // m, on the ground
};

TrialHooks defaultHooks();

// Validates every robot's behaviour against the hooks (throws ConfigError).
void checkBehaviours(const Experiment& e, const TrialHooks& hooks);

}  // namespace simswift::experiment
