// The robot program's part of a scenario robot: what a program simswift
// composes (builtin) or configures (launched: its {config} file) does -- a
// behaviour, timed body actions, or a joint script over the held posture.
// It is the agent's own RobotSetup (agent/program/RobotSetup.hpp), read from
// the robot's map by RobotSetup's parser and written into a launched
// program's {config} by its writer. The body's part (team, pose, posture,
// pushes, buttons, body interface) stays the scenario's
// (sim/runner/Scenario.hpp), which gives the setup its identity when a
// program is made (robotSetup below).
#pragma once

#include <string>
#include <vector>

#include "common/config/YamlReader.hpp"
#include "agent/program/RobotSetup.hpp"

namespace simswift::runner {
struct Scenario;
}

namespace simswift::programs {

// Of the setup, the scenario holds script, actions, behaviour and
// behaviour_yaml; team, player, seed, start and posture are set by robotSetup.
using ProgramPart = agent::program::RobotSetup;

// A robot map's script:, actions: and behaviour: into p (absent keys keep
// p's values; `outside`: the actions entries the scenario takes itself).
void readProgramPart(const common::config::YamlReader& robot, ProgramPart& p,
                     const agent::program::OutsideAction& outside);
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

// What robot `index` of `sc` is set up with: its program part with the
// identity its body and the run give it (team, player, the program's seed,
// posture, and the start pose for a behaviour: the scenario's, in m). What a
// builtin program is composed from and what a launched program's {config}
// file holds (robotSetupYaml), the same for both.
agent::program::RobotSetup robotSetup(const runner::Scenario& sc, int index);

}  // namespace simswift::programs
