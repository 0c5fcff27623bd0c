// The robot program's part of a scenario robot: what a program simswift
// composes (builtin) or configures (launched: its {config} file) does -- a
// behaviour, timed body actions, or a joint script over the held posture.
// It is the agent's own RobotSetup (agent/program/RobotSetup.hpp), read from
// the robot's map by RobotSetup's parser and written into a launched
// program's {config} by its writer. The body's part (team, pose, posture,
// pushes, buttons, body interface) stays the scenario's
// (sim/runner/Scenario.hpp), which gives the setup its identity when a
// program is made (ProgramIdentity, robotSetup below). The scenario holds
// these types; nothing here reads the scenario.
#pragma once

#include <string>
#include <vector>

#include "common/config/YamlReader.hpp"
#include "common/nao/Postures.hpp"
#include "agent/program/RobotSetup.hpp"

namespace simswift::programs {

// What drives a scenario robot's body: agent/'s program in this process, or
// a program attached by name (started by hand, or by simswift when its
// LaunchSpec has a command: ProgramProcess.hpp).
enum class ProgramKind { Builtin, External };

// Of the setup, the scenario holds script, actions, behaviour and
// behaviour_yaml; team, player, seed, start and posture are set by robotSetup.
using ProgramPart = agent::program::RobotSetup;

// A robot map's script:, actions: and behaviour: into p (absent keys keep
// p's values; `outside`: the actions entries the scenario takes itself).
void readProgramPart(const common::config::YamlReader& robot, ProgramPart& p,
                     const agent::program::OutsideAction& outside);
// A robot map's actions: alone into p.actions (absent: p's kept), the
// entries `outside` takes left to the scenario (pushes, buttons).
void readProgramActions(const common::config::YamlReader& robot, ProgramPart& p,
                        const agent::program::OutsideAction& outside);
// A behaviour from its kind name and overrides as YAML flow text (the
// experiment's robots). A bad override is a ConfigError with where's file,
// line and key (the robot's behaviour key), saying which override and why
// ("behaviour.search: unknown key 'spin_fast' ..."). check: the same, kept nowhere.
void setBehaviour(ProgramPart& p, const std::string& kind, const std::string& overrides,
                  const common::config::ConfigPlace& where);
void checkBehaviour(const std::string& kind, const std::string& overrides, const common::config::ConfigPlace& where);
// The behaviour's kind name ("findball2017"); "script" if none.
const char* behaviourName(const ProgramPart& p);
// For the rest of sim/ (which names no robot-program type): every name a
// robot's `behaviour:` may take, from agent/behaviour's table of kinds
// (BehaviourConfig.hpp), then kScriptBehaviour; and the same as text,
// "findball2016, ..., striker or script", for messages.
inline constexpr const char* kScriptBehaviour = agent::behaviour::kScriptBehaviourName;
const std::vector<std::string>& behaviourNames();
std::string behaviourNamesText();

// What its body and the run give a robot's program (the Runner fills it
// from the scenario: sim/runner/Scenario.hpp programIdentity).
struct ProgramIdentity {
  int team = 0, player = 0;
  uint64_t seed = 0;                 // the program's own (its filters' random source)
  common::nao::Posture posture{};    // the body's start
  double x = 0, y = 0, theta = 0;    // m, m, rad; field frame: the body's start pose
  bool pushed = false;               // the scenario pushes the body
};

// What a robot is set up with: its program part with its identity (team,
// player, seed, posture, and the start pose for a behaviour). What a
// builtin program is composed from and what a launched program's {config}
// file holds (robotSetupYaml), the same for both.
agent::program::RobotSetup robotSetup(const ProgramPart& part, const ProgramIdentity& id);

}  // namespace simswift::programs
