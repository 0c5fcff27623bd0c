// How the reference robot program is set up: who it is, its random seed,
// and what it does (a behaviour, timed body actions, or a posture with a
// joint script). The one place the standard program is composed from it
// (composeProgram), whether it runs in the simulator's process (`program:
// builtin`) or as simswift-agent in its own (`program: {command: ...}`), so
// both run the same modules with the same configuration.
//
// Its config file (simswift-agent --config FILE), every key optional:
//
//   team: 19                 # SPL team number
//   player: 2
//   seed: 1000003            # the filters' random source
//   start: {x: -3.0, y: 1.5, theta: 0}   # m, m, rad (field frame): a known
//                                        # start pose for localisation
//                                        # (written and read as held: m)
//   behaviour: findball2017  # or {kind: findball2017, <overrides>}
//                            # (agent/behaviour/BehaviourYaml.hpp)
//   actions: [...]           # timed body actions (agent/motion/ActionYaml.hpp)
//   posture: stand           # stand, crouch, limp, zero: held when nothing else
//   script: [{t: 1, joint: HeadYaw, angle: 0.5}]  # joints over time
//
// The simulator's scenario gives a robot's behaviour, actions and script
// under the same keys (docs/runner.md), read by the same parser
// (readProgramKeys), and writes a launched program's file with
// robotSetupYaml. Errors name the file, the line and the key
// (common/config/ConfigError.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/blackboard/Localisation.hpp"
#include "common/config/YamlReader.hpp"
#include "agent/motion/ActionScript.hpp"
#include "agent/program/ModuleOrder.hpp"
#include "agent/program/ScriptedMotion.hpp"
#include "agent/program/Postures.hpp"

namespace agent::program {

struct RobotSetup {
  int team = 0, player = 1;
  uint64_t seed = 1;
  // Localisation's known start pose; used with a behaviour, as a team
  // placing its robots on a test field configures it. In m, as the config
  // file and the scenario give it, so writing and reading it back is exact;
  // composeProgram converts it to the blackboard's mm, once.
  struct StartPose {
    double x = 0, y = 0, theta = 0;  // m, m, rad; field frame
  };
  std::optional<StartPose> start;
  std::optional<behaviour::BehaviourConfig> behaviour;  // wins over actions and script
  std::string behaviour_yaml;  // the behaviour as its file wrote it (flow YAML), to write it on
  std::vector<motion::ActionStep> actions;
  Posture posture = Posture::Stand;
  std::vector<ScriptStep> script;
};

// The standard program (agent/program/ModuleOrder) for `s`: with a behaviour
// the behaviour module plans with the walk's top speeds; with actions the
// scripted behaviour runs them through the Motion module; otherwise Motion
// is the scripted posture and joint steps. `motion` (may be null) replaces
// the Motion module (a test's generator). `motion_config` is the Motion
// module's configuration (ProgramConfig::motion: walk, kick, get-ups; the
// behaviour plans with its walk's top speeds); the simulator's runner takes
// a test's through Programs::setMotionConfig (sim/programs).
ProgramConfig composeProgram(const RobotSetup& s, std::unique_ptr<framework::MotionGenerator> motion = nullptr,
                             const motion::MotionConfig& motion_config = motion::MotionConfig());

// One `script:` entry: {t, joint, angle[, duration, stiffness]} or {t, posture}.
ScriptStep readScriptStep(const common::config::YamlReader& r);

// An `actions:` entry its caller takes itself (the simulator's pushes and
// button presses, which act on the body from outside the program): returns
// true if it took `entry`, whose `t` (s) is t_s.
using OutsideAction = std::function<bool(const common::config::YamlReader& entry, double t_s)>;

// The keys of what the program does, from map `r`: script, actions and
// behaviour (absent keys keep s's values). The one parser of them: for the
// config file (readRobotSetup) and a scenario's robot (sim/programs). `r`
// is left unfinished (its other keys are the caller's).
void readProgramKeys(const common::config::YamlReader& r, RobotSetup& s, const OutsideAction& outside = {});
// The `actions:` list of `r` alone, the same way.
void readActions(const common::config::YamlReader& r, RobotSetup& s, const OutsideAction& outside = {});

// Reads the config file (format above). Throws common::config::ConfigError.
RobotSetup readRobotSetup(const std::string& path);
// Reads map `r` into `s` (keys absent keep s's values) and finishes it.
void readRobotSetup(const common::config::YamlReader& r, RobotSetup& s);
// The config file's text for `s` (read back by readRobotSetup to an equal
// setup; the behaviour from behaviour_yaml).
std::string robotSetupYaml(const RobotSetup& s);

}  // namespace agent::program
