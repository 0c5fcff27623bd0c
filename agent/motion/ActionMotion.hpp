// The Motion thread's tick. Every 10 ms: take the Behaviour's latest
// MotionRequest and the sensors, detect falls, run the generator the
// request (or the fall state) selects, clip to the joint limits and per-tick
// speeds, and publish odometry, posture, support foot and the active action.
//
// It sees the body only through libagent SensorValues / JointValues; the
// robot program runs it as its Motion thread's module (agent/program's
// MotionThreadModule: motion request in, motion state out).
//
// Units: angles rad, distances mm, times s.
#pragma once

#include <cstdint>

#include "agent/blackboard/Blackboard.hpp"
#include "agent/motion/Generators.hpp"
#include "agent/motion/JointLimits.hpp"
#include "agent/motion/Walk2014Generator.hpp"
#include "agent/framework/MotionGenerator.hpp"

namespace agent::motion {

struct MotionConfig {
  WalkConfig walk;
  KickConfig kick;
  double fall_angle = 0.8;       // rad: |AngleX| or |AngleY| beyond this = falling
  double fallen_angle = 1.0;     // rad: beyond this and still = lying down
  double settle_rate = 0.6;      // rad/s: gyro magnitude below which the body is "still"
  double settle_time = 0.3;      // s still before a fall counts as finished
  double upright_angle = 0.5;    // rad: below this after a get-up = standing again
  int max_getup_attempts = 6;    // then stay down (limp) instead of retrying forever
  int getup_rise_frames = 2;     // the last frames of a get-up (crouch, stand): tipping over there = fall limp
  float falling_stiffness = 0.0f;  // the safe limp fall (0 = limp, joints free)
  bool auto_getup = true;        // get up after a fall unless DEAD / LIMP is requested
  float limp_stiffness = 0.1f;   // LIMP action
  double lifted_weight = 4.0;    // kg (the FSR unit; standing: 5.3) on both feet below which the robot is in the air
  double transition_time = 0.8;  // s to move to the stand from another posture
  // Get-up sequences; empty = the built-in ones (Generators.hpp).
  std::vector<Keyframe> getup_front, getup_back;
};

class ActionMotion : public framework::MotionGenerator {
 public:
  explicit ActionMotion(const MotionConfig& cfg = MotionConfig());

  // The Behaviour's request, followed from the next tick on (a NONE body
  // keeps the current body command).
  void setRequest(const blackboard::MotionRequest& r) { request_ = r; }
  // What the body is doing after the last tick (odometry, posture, ...).
  const blackboard::MotionState& state() const { return state_; }

  // framework::MotionGenerator: one tick at sim_time_us; `out` is the command.
  void tick(const common::libagent::SensorValues& sensors, int64_t sim_time_us, common::libagent::JointValues& out) override;

  // Same, by time in s, for tests and tools.
  void tickSeconds(const common::libagent::SensorValues& sensors, double time_s, common::libagent::JointValues& out);

  enum class Mode { Walk, Kick, Crouch, Transition, Falling, Fallen, Getup, Limp, Dead };
  Mode mode() const { return mode_; }
  const Walk2014Generator& walk() const { return walk_; }
  int getupAttempts() const { return getup_attempts_; }
  const MotionConfig& config() const { return cfg_; }

 private:
  // One tick's inputs, read once from the request and the sensors.
  struct TickInput {
    const common::libagent::SensorValues& sensors;
    const blackboard::MotionRequest& req;
    blackboard::ActionType want;  // the body command followed (last non-NONE)
    double dt;                    // s, the tick length
    double ax, ay;                // rad, InertialSensor_AngleX / AngleY
    double tilt;                  // rad, max(|ax|, |ay|)
    double rate;                  // rad/s, roll and pitch rate magnitude
  };

  double tickLength(double time_s);
  TickInput readInputs(const common::libagent::SensorValues& sensors, double dt);
  void startFromLastCommand(const common::libagent::SensorValues& sensors, common::libagent::JointValues& out);
  void overrideMode(const TickInput& in);
  // Runs the current mode's generator into `out`; true while the walk steps.
  bool runMode(const TickInput& in, common::libagent::JointValues& out);
  bool tickWalk(const TickInput& in, common::libagent::JointValues& out);
  void handRequestToWalk(const TickInput& in, const common::libagent::JointValues& out);
  void runKick(const TickInput& in, common::libagent::JointValues& out);
  void tickKick(const TickInput& in, common::libagent::JointValues& out);
  void tickCrouch(const TickInput& in, common::libagent::JointValues& out);
  void tickTransition(const TickInput& in, common::libagent::JointValues& out);
  void tickLimp(const TickInput& in, common::libagent::JointValues& out);
  void tickDead(const TickInput& in, common::libagent::JointValues& out);
  void tickFalling(const TickInput& in, common::libagent::JointValues& out);
  void tickFallen(const TickInput& in, common::libagent::JointValues& out);
  void startGetup(const TickInput& in);
  void tickGetup(const TickInput& in, common::libagent::JointValues& out);
  void startFalling();
  void commandHeadAndClip(const TickInput& in, common::libagent::JointValues& out);
  void integrateOdometry();
  void startTransitionToStand(const common::libagent::JointValues& from);
  void publish(const blackboard::MotionRequest& req, double time_s, bool stepping);

  MotionConfig cfg_;
  blackboard::MotionRequest request_;
  blackboard::MotionState state_;
  Walk2014Generator walk_;
  KickGenerator kick_;
  KeyframeGenerator keyframes_;
  HeadGenerator head_;
  Clipper clipper_;
  Mode mode_ = Mode::Walk;
  blackboard::BodyCommand body_;      // last non-NONE body command
  blackboard::Odometry odometry_;
  blackboard::BodyState posture_ = blackboard::BodyState::STANDING;
  blackboard::Foot support_ = blackboard::Foot::LEFT;
  common::libagent::JointValues last_cmd_{};
  bool have_last_ = false;
  double last_time_ = -1;
  double still_time_ = 0;   // s the body has been still while falling
  double lifted_time_ = 0;  // s with no weight on the feet
  int64_t kick_sequence_ = -1;
  int64_t ticks_ = 0;
  int getup_attempts_ = 0;     // total, for tests and tools
  int getups_since_up_ = 0;    // attempts since last standing, for max_getup_attempts
  bool getup_front_ = true;
};

}  // namespace agent::motion
