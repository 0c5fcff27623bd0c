// The one place where the robot program's modules are chosen and ordered.
//
//   Perception thread (each camera frame, 30 Hz of simulated time):
//     [perception step] -> game state -> vision adapter -> localisation ->
//     ball tracker -> team receive -> [behaviour] -> team send
//   Motion thread (each 10 ms tick):
//     touch -> motion -> effector
//
// The robot program itself provides `sensors` (before the Motion modules)
// and `frame` (before the Perception modules). The bracketed modules are
// optional: a PerceptionStep given by a test or tool, and a behaviour (the
// scenario's action script or one of agent/behaviour's). Without a behaviour
// nothing writes the behaviour request, so Motion must then be a generator
// (a held posture or joint script) -- the start-up check says so otherwise.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "agent/libagent/SimExtensions.hpp"
#include "agent/localisation/LocalisationModule.hpp"
#include "agent/motion/ActionScript.hpp"
#include "agent/motion/MotionModule.hpp"
#include "agent/perception/PerceptionModules.hpp"
#include "agent/program/MotionGenerator.hpp"
#include "agent/program/Module.hpp"
#include "agent/program/StandardModules.hpp"

namespace agent::program {

struct ProgramConfig {
  int team = 0, player = 1;
  uint64_t seed = 1;  // the filters' random source (scenario seed and robot)
  // Motion: a generator replaces the Motion module (the walk, kicks, falls).
  std::unique_ptr<MotionGenerator> motion_generator;
  motion::MotionConfig motion;
  // Behaviour: a scenario's timed body actions (empty and no `behaviour`: none).
  std::vector<motion::ActionStep> actions;
  std::unique_ptr<Module> behaviour;  // a behaviour module (wins over actions)
  std::unique_ptr<PerceptionStep> perception_step;
  localisation::LocalisationModuleConfig localisation;
  perception::BallTrackerConfig ball;
  perception::VisionAdapterConfig vision;
  // The simulator's extension objects (game state, team link); null: no
  // game (unknown, PLAYING) and no teammates.
  libagent::SimExtensions* extensions = nullptr;
  // Called by each thread before every step (Motion tick, Perception frame),
  // from that thread. For tests (seeded sleeps that scramble thread timing);
  // empty: nothing.
  std::function<void(ThreadId)> step_hook;
};

// Fills `schedule` in the standard order. `board` is the program's Blackboard
// (the Motion module keeps a reference); `effector` sends the actuators.
void buildSchedule(ProgramConfig& cfg, blackboard::Blackboard& board, EffectorModule::Sink effector,
                   ModuleSchedule& schedule);

}  // namespace agent::program
