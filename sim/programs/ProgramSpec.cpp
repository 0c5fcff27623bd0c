#include "sim/programs/ProgramSpec.hpp"

#include "agent/behaviour/BehaviourYaml.hpp"

namespace simswift::programs {

void readProgramPart(const common::config::YamlReader& robot, ProgramPart& p,
                     const agent::program::OutsideAction& outside) {
  agent::program::readProgramKeys(robot, p, outside);
}

void readProgramActions(const common::config::YamlReader& robot, ProgramPart& p,
                        const agent::program::OutsideAction& outside) {
  agent::program::readActions(robot, p, outside);
}

namespace {

// The behaviour's reader reads the overrides as a document of their own
// (named by where's file, its lines theirs): its error is re-raised at
// `where`, with what it says after its own file and line.
std::optional<agent::behaviour::BehaviourConfig> behaviourAt(const std::string& kind, const std::string& overrides,
                                                             const common::config::ConfigPlace& where,
                                                             std::string* yaml) {
  using common::config::ConfigError;
  try {
    return agent::behaviour::behaviourFromText(kind, overrides, where.file, yaml);
  } catch (const ConfigError& e) {
    const std::string own = e.file + ":" + std::to_string(e.line) + ": ";
    const std::string what = e.what();
    throw ConfigError(where.file, where.line, where.key,
                      what.rfind(own, 0) == 0 ? what.substr(own.size()) : what);
  }
}

}  // namespace

void setBehaviour(ProgramPart& p, const std::string& kind, const std::string& overrides,
                  const common::config::ConfigPlace& where) {
  p.behaviour = behaviourAt(kind, overrides, where, &p.behaviour_yaml);
}

void checkBehaviour(const std::string& kind, const std::string& overrides, const common::config::ConfigPlace& where) {
  behaviourAt(kind, overrides, where, nullptr);
}

const char* behaviourName(const ProgramPart& p) {
  return p.behaviour ? agent::behaviour::behaviourKindName(p.behaviour->kind) : kScriptBehaviour;
}

const std::vector<std::string>& behaviourNames() { return agent::behaviour::behaviourNames(); }

std::string behaviourNamesText() { return agent::behaviour::behaviourNamesText(); }

agent::program::RobotSetup robotSetup(const ProgramPart& part, const ProgramIdentity& id) {
  agent::program::RobotSetup s = part;
  s.team = id.team;
  s.player = id.player;
  s.seed = id.seed;
  s.posture = id.posture;
  s.start.reset();
  if (part.behaviour) s.start = agent::program::RobotSetup::StartPose{id.x, id.y, id.theta};  // m, as the scenario's
  // Pushes only: a NONE step keeps the script's STAND (the body is pushed,
  // the Motion module runs).
  if (!s.behaviour && s.actions.empty() && id.pushed) s.actions.push_back({});
  return s;
}

}  // namespace simswift::programs
