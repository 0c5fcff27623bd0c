// The one place where the robot program's modules are chosen and ordered.
//
//   Perception thread (each camera frame, 30 Hz of simulated time):
//     [perception step] -> game state -> vision adapter -> localisation ->
//     ball tracker -> team receive -> [behaviour] -> team send
//   Motion thread (each 10 ms tick):
//     motion -> effector
//
// The robot program itself provides `sensors` (before the Motion modules)
// and `frame`, `game_controller` and `team_inbox` (from its devices, before
// the Perception modules), and reads `team_outbox` (onto its team
// transport) and `findball` (the simulator's FindBall view draws it). The bracketed modules are optional:
// a PerceptionStep given by a test or tool, and a behaviour (the scenario's
// action script, one of agent/behaviour's, or a test's, bench's or tool's
// RequestedBehaviour: agent/behaviour/RequestedBehaviour.hpp). Without a behaviour nothing
// writes the motion request, so Motion must then be a generator (a held
// posture or joint script) -- the start-up check says so otherwise.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "common/libagent/SimExtensions.hpp"
#include "agent/behaviour/BehaviourModule.hpp"
#include "agent/localisation/LocalisationModule.hpp"
#include "agent/motion/ActionScript.hpp"
#include "agent/motion/ActionMotion.hpp"
#include "agent/perception/PerceptionModules.hpp"
#include "agent/framework/ModuleSchedule.hpp"
#include "agent/framework/MotionGenerator.hpp"
#include "agent/framework/PerceptionStep.hpp"
#include "agent/program/StandardModules.hpp"

namespace agent::program {

struct ProgramConfig {
  int team = 0, player = 1;
  uint64_t seed = 1;  // the filters' random source (scenario seed and robot)
  // Motion: a generator replaces the Motion module (the walk, kicks, falls).
  std::unique_ptr<framework::MotionGenerator> motion_generator;
  motion::MotionConfig motion;  // the Motion module's (composeProgram's motion_config)
  // Behaviour: a scenario's timed body actions (empty and no `behaviour`: none).
  std::vector<motion::ActionStep> actions;
  // One of agent/behaviour's, built at start for the body the program
  // drives (its lens: BehaviourModule's camera_hfov unless set).
  std::optional<behaviour::BehaviourModuleConfig> behaviour_config;
  std::unique_ptr<framework::Module> behaviour;  // a test's or tool's module (wins over the above and actions)
  std::unique_ptr<framework::PerceptionStep> perception_step;
  localisation::LocalisationModuleConfig localisation;
  perception::BallTrackerConfig ball;
  perception::VisionAdapterConfig vision;
  // The simulator's extension objects (game state, team link), the program's
  // devices; null: no game (unknown, PLAYING) and no teammates.
  common::libagent::SimExtensions* extensions = nullptr;
  // Called by each thread before every step (Motion tick, Perception frame),
  // from that thread. For tests (seeded sleeps that scramble thread timing);
  // empty: nothing.
  std::function<void(framework::ThreadId)> step_hook;
};

// Fills `schedule` in the standard order. `effector` sends the actuators;
// `images` are the rendered camera images a PerceptionStep sees (null: none);
// `lens` is the body's (BodyConnection::cameraLens): cfg.behaviour_config's
// camera_hfov, if unset, becomes its horizontal field of view.
void buildSchedule(ProgramConfig& cfg, EffectorModule::Sink effector, const common::libagent::CameraImages* images,
                   const common::nao::CameraLens& lens, framework::ModuleSchedule& schedule);

}  // namespace agent::program
