#include "sim/programs/ProgramSpec.hpp"

#include "agent/behaviour/BehaviourYaml.hpp"
#include "sim/runner/Scenario.hpp"

namespace simswift::programs {

void readProgramPart(const common::config::YamlReader& robot, ProgramPart& p,
                     const agent::program::OutsideAction& outside) {
  agent::program::readProgramKeys(robot, p, outside);
}

void setBehaviour(ProgramPart& p, const std::string& kind, const std::string& overrides, const std::string& where) {
  p.behaviour = agent::behaviour::behaviourFromText(kind, overrides, where, &p.behaviour_yaml);
}

void checkBehaviour(const std::string& kind, const std::string& overrides, const std::string& where) {
  agent::behaviour::behaviourFromText(kind, overrides, where);
}

const char* behaviourName(const ProgramPart& p) {
  return p.behaviour ? agent::behaviour::behaviourKindName(p.behaviour->kind) : kScriptBehaviour;
}

const std::vector<std::string>& behaviourNames() { return agent::behaviour::behaviourNames(); }

std::string behaviourNamesText() { return agent::behaviour::behaviourNamesText(); }

agent::program::RobotSetup robotSetup(const runner::Scenario& sc, int index) {
  const runner::RobotSpec& r = sc.robots[index];
  agent::program::RobotSetup s = r.setup;
  s.team = r.team;
  s.player = r.player;
  s.seed = runner::programSeed(sc.seed, index);
  s.posture = r.posture;
  s.start.reset();
  if (r.setup.behaviour) s.start = agent::program::RobotSetup::StartPose{r.x, r.y, r.theta};  // m, as the scenario's
  // Pushes only: a NONE step keeps the script's STAND (the body is pushed,
  // the Motion module runs).
  if (!s.behaviour && s.actions.empty() && !r.pushes.empty()) s.actions.push_back({});
  return s;
}

}  // namespace simswift::programs
