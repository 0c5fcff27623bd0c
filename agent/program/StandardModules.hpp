// The robot program's own small modules: the Motion thread's touch, motion
// and effector steps, the game state reader, team receive / send, and
// adapters that run a MotionGenerator or a PerceptionStep as a module.
#pragma once

#include <functional>
#include <memory>

#include "agent/comms/GameStateReader.hpp"
#include "agent/comms/TeamReceiver.hpp"
#include "agent/comms/TeamSender.hpp"
#include "agent/comms/TeamTransport.hpp"
#include "agent/libagent/GameState.hpp"
#include "agent/motion/MotionModule.hpp"
#include "agent/program/MotionGenerator.hpp"
#include "agent/program/Module.hpp"

namespace agent::program {

// sensors -> touch: buttons and bumpers, chest presses counted.
class TouchModule : public Module {
 public:
  const char* name() const override { return "touch"; }
  std::vector<SectionId> reads() const override { return {SectionId::Sensors}; }
  std::vector<SectionId> writes() const override { return {SectionId::Touch}; }
  void run(blackboard::Blackboard& board) override;

 private:
  bool chest_down_ = false;
  int presses_ = 0;
};

// sensors + behaviour request -> motion + actuators: the Motion module
// (agent/motion) on this program's Blackboard.
class MotionThreadModule : public Module {
 public:
  MotionThreadModule(blackboard::Blackboard& board, const motion::MotionConfig& cfg)
      : motion_(board, cfg) {}
  const char* name() const override { return "motion"; }
  std::vector<SectionId> reads() const override { return {SectionId::Sensors, SectionId::BehaviourRequest}; }
  std::vector<SectionId> writes() const override { return {SectionId::Motion, SectionId::Actuators}; }
  void run(blackboard::Blackboard& board) override;
  motion::MotionModule& motion() { return motion_; }

 private:
  motion::MotionModule motion_;
  libagent::JointValues cmd_{};
};

// sensors -> motion + actuators: a replaceable MotionGenerator (a held
// posture, a joint script, a test's generator). Its Motion section has the
// tick and time only (no odometry: the generator does not walk).
class GeneratorModule : public Module {
 public:
  explicit GeneratorModule(std::unique_ptr<MotionGenerator> g) : gen_(std::move(g)) {}
  const char* name() const override { return "motion (generator)"; }
  std::vector<SectionId> reads() const override { return {SectionId::Sensors}; }
  std::vector<SectionId> writes() const override { return {SectionId::Motion, SectionId::Actuators}; }
  void run(blackboard::Blackboard& board) override;
  MotionGenerator* generator() { return gen_.get(); }

 private:
  std::unique_ptr<MotionGenerator> gen_;
  libagent::JointValues cmd_{};
  bool first_ = true;
  int64_t ticks_ = 0;
};

// actuators -> the body (through the robot program's connection).
class EffectorModule : public Module {
 public:
  using Sink = std::function<void(const blackboard::ActuatorRequest&)>;
  explicit EffectorModule(Sink sink) : sink_(std::move(sink)) {}
  const char* name() const override { return "effector"; }
  std::vector<SectionId> reads() const override { return {SectionId::Actuators}; }
  std::vector<SectionId> writes() const override { return {}; }
  void run(blackboard::Blackboard& board) override { sink_(board.actuators.read()); }

 private:
  Sink sink_;
};

// frame -> (its own state): a PerceptionStep (tests, image consumers).
class PerceptionStepModule : public Module {
 public:
  explicit PerceptionStepModule(std::unique_ptr<PerceptionStep> step) : step_(std::move(step)) {}
  const char* name() const override { return "perception step"; }
  std::vector<SectionId> reads() const override { return {SectionId::Frame}; }
  std::vector<SectionId> writes() const override { return {}; }
  // Needs the raw camera frame (the program hands it over before running).
  void setFrame(const libagent::CameraFrame* f) { frame_ = f; }
  void run(blackboard::Blackboard&) override {
    if (frame_) step_->step(*frame_);
  }
  PerceptionStep& step() { return *step_; }

 private:
  std::unique_ptr<PerceptionStep> step_;
  const libagent::CameraFrame* frame_ = nullptr;
};

// -> game state, from the game-state extension object (GameStateReader).
// Without one (null: a program attached by name, a bench tool) the game is
// unknown (known = false: a test field, always PLAYING).
class GameStateModule : public Module {
 public:
  GameStateModule(int team, int player, const libagent::GameStateBlock* block)
      : reader_(team, player), block_(block) {
    info_.team_number = team;
    info_.player_number = player;
  }
  const char* name() const override { return "game state"; }
  std::vector<SectionId> reads() const override { return {SectionId::Frame}; }
  std::vector<SectionId> writes() const override { return {SectionId::GameState}; }
  void run(blackboard::Blackboard& board) override;

 private:
  comms::GameStateReader reader_;
  const libagent::GameStateBlock* block_;
  blackboard::GameInfo info_;
};

// -> team: teammates' SPL standard messages through the transport
// (TeamReceiver parses them; malformed ones are counted and dropped), as
// field-frame reports. Without a transport nothing arrives.
class TeamReceiveModule : public Module {
 public:
  TeamReceiveModule(int team, int player, std::shared_ptr<comms::TeamTransport> transport)
      : receiver_(team, player), transport_(std::move(transport)) {
    info_.team_number = team;
    info_.player_number = player;
  }
  const char* name() const override { return "team receive"; }
  std::vector<SectionId> reads() const override { return {SectionId::Frame}; }
  std::vector<SectionId> writes() const override { return {SectionId::Team}; }
  void run(blackboard::Blackboard& board) override;

 private:
  comms::TeamReceiver receiver_;
  std::shared_ptr<comms::TeamTransport> transport_;
  blackboard::TeamInfo info_;
};

// localisation + ball + motion (fallen) [+ findball] -> teammates: our SPL
// standard message at 5 Hz (TeamSender) through the transport. With a
// behaviour that publishes findball, its SearchPayload bytes go into the
// message's free data area and its search point into walkingTo.
class TeamSendModule : public Module {
 public:
  TeamSendModule(int team, int player, std::shared_ptr<comms::TeamTransport> transport, bool with_findball = false)
      : sender_(team, player), transport_(std::move(transport)), player_(player), with_findball_(with_findball) {}
  const char* name() const override { return "team send"; }
  std::vector<SectionId> reads() const override {
    std::vector<SectionId> r{SectionId::Frame, SectionId::Localisation, SectionId::Ball, SectionId::Motion};
    if (with_findball_) r.push_back(SectionId::FindBall);
    return r;
  }
  std::vector<SectionId> writes() const override { return {}; }
  void run(blackboard::Blackboard& board) override;
  const comms::TeamSender& sender() const { return sender_; }

 private:
  comms::TeamSender sender_;
  std::shared_ptr<comms::TeamTransport> transport_;
  int player_;
  bool with_findball_;
};

}  // namespace agent::program
