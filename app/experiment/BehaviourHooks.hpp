// The behaviours of agent/behaviour in experiments: findball2016,
// findball2017 and striker become the trial scenario's robot `behaviour:`
// (through the program side, sim/programs/ProgramSpec.hpp: the robot's
// config overrides parsed by agent/behaviour/BehaviourYaml, so
// a bad override is refused before any trial, naming the behaviour's file
// and line). Script robots keep their actions. The trial's start (penalised
// at the start poses, then PLAYING) is runTrial's, the same for every
// behaviour.
#pragma once

#include "app/experiment/TrialHooks.hpp"

namespace simswift::experiment {

class RobotBehaviours : public BehaviourFactory {
 public:
  void check(const Experiment& e, const ExperimentRobot& r) const override;
  void configure(const Experiment& e, const TrialSpec& t, runner::Scenario& sc) const override;
};

// The trial hooks of simswift: RobotBehaviours and the VisionFoundRule.
TrialHooks behaviourHooks();

}  // namespace simswift::experiment
