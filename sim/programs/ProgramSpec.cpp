#include "sim/programs/ProgramSpec.hpp"

#include "agent/behaviour/BehaviourYaml.hpp"
#include "agent/motion/ActionYaml.hpp"
#include "sim/runner/Scenario.hpp"

namespace simswift::programs {

void readScriptStep(const agent::config::YamlReader& r, ProgramPart& p) {
  p.script.push_back(agent::program::readScriptStep(r));
}

void readBodyAction(const agent::config::YamlReader& r, double t_s, ProgramPart& p) {
  p.actions.push_back(agent::motion::readBodyAction(r, t_s));
}

void readBehaviour(const agent::config::YamlReader& robot, ProgramPart& p) {
  p.behaviour = agent::behaviour::readBehaviour(robot, &p.behaviour_yaml);
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
  agent::program::RobotSetup s;
  s.team = r.team;
  s.player = r.player;
  s.seed = runner::programSeed(sc.seed, index);
  if (r.behaviour) s.start = agent::blackboard::FieldPose{r.x * 1000.0, r.y * 1000.0, r.theta};
  s.behaviour = r.behaviour;
  s.behaviour_yaml = r.behaviour_yaml;
  s.actions = r.actions;
  // Pushes only: a NONE step keeps the script's STAND (the body is pushed,
  // the Motion module runs).
  if (!r.behaviour && s.actions.empty() && !r.pushes.empty()) s.actions.push_back({});
  s.posture = r.posture;
  s.script = r.script;
  return s;
}

}  // namespace simswift::programs
