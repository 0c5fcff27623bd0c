// The robot program's part of a scenario robot: what a program simswift
// composes (builtin) or configures (launched: its {config} file) is set up
// with -- a behaviour, timed body actions, or a joint script over the held
// posture. The scenario (sim/runner/Scenario.hpp) reads these keys through
// the readers here, so nothing outside sim/programs names the robot
// program's types. The body's part (team, pose, posture, pushes, buttons,
// libagent release) stays the scenario's.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/config/YamlReader.hpp"
#include "agent/motion/ActionScript.hpp"
#include "agent/program/MotionGenerator.hpp"
#include "agent/program/RobotSetup.hpp"

namespace simswift::runner {
struct Scenario;
}

namespace simswift::programs {

struct ProgramPart {
  // Joint steps over the held posture (script:).
  std::vector<agent::program::ScriptStep> script;
  // Body actions over time, run by the Motion module (agent/motion), e.g.
  //   actions: [{t: 1, action: walk, forward: 300, left: 0, turn: 0},
  //             {t: 6, action: kick, foot: right, power: 1, direction: 0}]
  // forward/left mm/s, turn rad/s, direction rad.
  std::vector<agent::motion::ActionStep> actions;
  // behaviour: the robot code's behaviour (agent/behaviour); empty = script
  // (the actions above).
  std::optional<agent::behaviour::BehaviourConfig> behaviour;
  std::string behaviour_yaml;  // the same as flow YAML (a launched program's {config} file)
};

// One `script:` entry: {t, joint, angle[, duration, stiffness]} or {t, posture}.
void readScriptStep(const agent::config::YamlReader& r, ProgramPart& p);
// One `actions:` entry holding `action:` (t already read, s).
void readBodyAction(const agent::config::YamlReader& r, double t_s, ProgramPart& p);
// A robot map's `behaviour:` (which it must have).
void readBehaviour(const agent::config::YamlReader& robot, ProgramPart& p);
// A behaviour from its kind name and overrides as YAML flow text (the
// experiment's robots); errors name `where`. check: the same, kept nowhere.
void setBehaviour(ProgramPart& p, const std::string& kind, const std::string& overrides, const std::string& where);
void checkBehaviour(const std::string& kind, const std::string& overrides, const std::string& where);
// The behaviour's kind name ("findball2017"); "script" if none.
const char* behaviourName(const ProgramPart& p);
// For the rest of sim/ (which names no robot-program type): every name a
// robot's `behaviour:` may take, from agent/behaviour's table of kinds
// (BehaviourConfig.hpp), then kScriptBehaviour; and the same as text,
// "findball2016, ..., striker or script", for messages.
inline constexpr const char* kScriptBehaviour = agent::behaviour::kScriptBehaviourName;
const std::vector<std::string>& behaviourNames();
std::string behaviourNamesText();

// What robot `index` of `sc` is set up with (agent/program/RobotSetup.hpp):
// what a builtin program is composed from and what a launched program's
// {config} file holds.
agent::program::RobotSetup robotSetup(const runner::Scenario& sc, int index);

}  // namespace simswift::programs
