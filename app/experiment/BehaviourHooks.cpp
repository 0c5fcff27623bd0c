#include "app/experiment/BehaviourHooks.hpp"

#include "sim/programs/ProgramSpec.hpp"

namespace simswift::experiment {

void RobotBehaviours::check(const Experiment&, const ExperimentRobot& r) const {
  if (r.isScript()) return;
  programs::checkBehaviour(r.behaviour, r.config_yaml, r.behaviour_where);
}

void RobotBehaviours::configure(const Experiment& e, const TrialSpec& t, runner::Scenario& sc) const {
  const Setup& s = e.setups[t.setup];
  for (size_t i = 0; i < s.robots.size() && i < sc.robots.size(); ++i) {
    const ExperimentRobot& r = s.robots[i];
    if (r.isScript()) continue;  // its actions are already set
    programs::setBehaviour(sc.robots[i].setup, r.behaviour, r.config_yaml, r.behaviour_where);
  }
}

TrialHooks behaviourHooks() {
  TrialHooks h;
  h.behaviours = std::make_shared<RobotBehaviours>();
  h.found = std::make_shared<VisionFoundRule>();
  return h;
}

}  // namespace simswift::experiment
