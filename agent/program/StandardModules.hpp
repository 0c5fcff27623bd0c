// The robot program's own small modules: the Motion thread's motion and
// effector steps, the game state reader, team receive / send, and
// adapters that run a MotionGenerator or a PerceptionStep as a module.
#pragma once

#include <functional>
#include <memory>

#include "agent/comms/GameStateReader.hpp"
#include "agent/comms/TeamReceiver.hpp"
#include "agent/comms/TeamSender.hpp"
#include "common/libagent/GameState.hpp"
#include "agent/motion/ActionMotion.hpp"
#include "agent/program/ScriptedMotion.hpp"
#include "agent/framework/Module.hpp"
#include "agent/framework/PerceptionStep.hpp"

namespace agent::program {

namespace bb = agent::blackboard;
using framework::IfProvided;
using framework::ModuleOf;
using framework::Reads;
using framework::Writes;

// sensors + motion request -> motion + actuators: the Motion module
// (agent/motion).
class MotionThreadModule
    : public ModuleOf<Reads<bb::SensorFrame, bb::MotionRequest>, Writes<bb::MotionState, bb::ActuatorRequest>> {
 public:
  explicit MotionThreadModule(const motion::MotionConfig& cfg) : motion_(cfg) {}
  const char* name() const override { return "motion"; }
  motion::ActionMotion& motion() { return motion_; }

 private:
  void update(const In& in, Out& out) override;
  motion::ActionMotion motion_;
  common::libagent::JointValues cmd_{};
};

// sensors -> motion + actuators: a replaceable MotionGenerator (a held
// posture, a joint script, a test's generator). Its Motion section has the
// tick and time only (no odometry: the generator does not walk).
class GeneratorModule : public ModuleOf<Reads<bb::SensorFrame>, Writes<bb::MotionState, bb::ActuatorRequest>> {
 public:
  explicit GeneratorModule(std::unique_ptr<framework::MotionGenerator> g) : gen_(std::move(g)) {}
  const char* name() const override { return "motion (generator)"; }
  framework::MotionGenerator* generator() { return gen_.get(); }

 private:
  void update(const In& in, Out& out) override;
  std::unique_ptr<framework::MotionGenerator> gen_;
  common::libagent::JointValues cmd_{};
  bool first_ = true;
  int64_t ticks_ = 0;
};

// actuators -> the body (through the robot program's connection).
class EffectorModule : public ModuleOf<Reads<bb::ActuatorRequest>, Writes<>> {
 public:
  using Sink = std::function<void(const bb::ActuatorRequest&)>;
  explicit EffectorModule(Sink sink) : sink_(std::move(sink)) {}
  const char* name() const override { return "effector"; }

 private:
  void update(const In& in, Out&) override { sink_(in.get<bb::ActuatorRequest>()); }
  Sink sink_;
};

// frame -> (its own state): a PerceptionStep (tests, image consumers). The
// step sees the camera frame as libagent delivered it, rebuilt from the
// frame section, and the rendered images (null: none rendered).
class PerceptionStepModule : public ModuleOf<Reads<bb::FrameInfo>, Writes<>> {
 public:
  PerceptionStepModule(std::unique_ptr<framework::PerceptionStep> step, const common::libagent::CameraImages* images)
      : step_(std::move(step)) {
    step_->setImages(images);
  }
  const char* name() const override { return "perception step"; }
  framework::PerceptionStep& step() { return *step_; }

 private:
  void update(const In& in, Out&) override;
  std::unique_ptr<framework::PerceptionStep> step_;
  common::libagent::CameraFrame frame_{};
};

// game controller data -> game state (GameStateReader). Without a
// game-state device (a program attached by name, a bench tool) the game is
// unknown (known = false: a test field, always PLAYING).
class GameStateModule : public ModuleOf<Reads<bb::FrameInfo, bb::GameControllerData>, Writes<bb::GameInfo>> {
 public:
  GameStateModule(int team, int player) : reader_(team, player) {
    info_.team_number = team;
    info_.player_number = player;
  }
  const char* name() const override { return "game state"; }

 private:
  void update(const In& in, Out& out) override;
  comms::GameStateReader reader_;
  blackboard::GameInfo info_;
};

// team inbox -> team: teammates' SPL standard messages (TeamReceiver parses
// them; malformed ones are counted and dropped), as field-frame reports.
// Without a team transport nothing arrives.
class TeamReceiveModule : public ModuleOf<Reads<bb::FrameInfo, bb::TeamInbox>, Writes<bb::TeamInfo>> {
 public:
  TeamReceiveModule(int team, int player) : receiver_(team, player) {
    info_.team_number = team;
    info_.player_number = player;
  }
  const char* name() const override { return "team receive"; }

 private:
  void update(const In& in, Out& out) override;
  comms::TeamReceiver receiver_;
  blackboard::TeamInfo info_;
};

// localisation + ball + motion (fallen) [+ findball] -> team outbox: our
// SPL standard message at 5 Hz (TeamSender), which the robot program puts
// on its team transport. With a behaviour that publishes findball, its
// SearchPayload bytes go into the message's free data area and its search
// point into walkingTo (without one the section keeps its default: no
// data, no point).
class TeamSendModule : public ModuleOf<Reads<bb::FrameInfo, bb::LocalisationEstimate, bb::BallEstimate, bb::MotionState,
                                             IfProvided<bb::FindBallInfo>>,
                                       Writes<bb::TeamOutbox>> {
 public:
  TeamSendModule(int team, int player) : sender_(team, player), player_(player) {}
  const char* name() const override { return "team send"; }

 private:
  void update(const In& in, Out& out) override;
  comms::TeamSender sender_;
  int player_;
};

}  // namespace agent::program
