// Shared harness for the Motion physics tests' (tests/runner) and the kick
// and get-up tuning tools' way of driving the walk (in harness/, which both
// may include; no GoogleTest in it): one robot in the lock-step runner running the
// production schedule (agent/program/ModuleOrder.cpp) inline: the test
// plays Behaviour through a RequestedBehaviour in the Perception thread's
// behaviour slot (agent/behaviour/RequestedBehaviour.hpp), which writes the
// program's MotionRequest section each camera frame (30 Hz); the standard
// MotionThreadModule and EffectorModule run in the Motion thread. Between
// ticks the harness reads the program's Blackboard (MotionState) and checks
// the command the simulator latched (Runner::lastCommand) against the joint
// limits and the per-tick speed limit (the clipper's promise).
// A request set between ticks reaches Motion on the first Motion tick after
// the next camera frame: 2-5 ticks (20-50 ms) later, where a Motion step
// that took it directly would have had it on the next tick (10 ms).
// Units: m and rad in the field frame (world), mm in the robot frame (odometry).
#pragma once

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "agent/behaviour/RequestedBehaviour.hpp"
#include "agent/blackboard/Blackboard.hpp"
#include "agent/program/StandardModules.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"

namespace motion_test {

// Down or on the way up: the postures a pushed-over robot passes through.
inline bool downOrGettingUp(agent::blackboard::BodyState p) {
  using P = agent::blackboard::BodyState;
  return p == P::FALLEN_FORWARD || p == P::FALLEN_BACKWARD || p == P::FALLEN_SIDEWAYS || p == P::GETTING_UP;
}

// Checks every command the body gets against the joint limits and the
// per-tick speed limit; keeps the last command and the sensors it answered.
class CommandCheck {
 public:
  // After each tick: `cmd` latched this tick, `sensed` published this tick.
  void check(const common::libagent::ActuatorCommand& cmd, const common::libagent::SensorValues& sensed) {
    last_command = cmd.joints;
    last_sensed = sensed;
    const auto& lim = agent::motion::jointLimits();
    for (int i = 0; i < common::libagent::kNumJoints; ++i) {
      const float a = cmd.joints.angles[i];
      if (!(a >= lim[i].lower && a <= lim[i].upper)) ++limit_violations;
      if (have_prev_ && std::fabs(a - prev_[i]) > lim[i].max_velocity * agent::motion::kMotionTick + 1e-6)
        ++speed_violations;
      prev_[i] = a;
    }
    have_prev_ = true;
    ++ticks;
  }
  int64_t limit_violations = 0, speed_violations = 0, ticks = 0;
  common::libagent::JointValues last_command{};
  common::libagent::SensorValues last_sensed{};

 private:
  float prev_[common::libagent::kNumJoints] = {};
  bool have_prev_ = false;
};

struct Pose2 {
  double x, y, theta;  // m, m, rad (field frame)
};

class MotionHarness {
 public:
  // A scenario with one robot at (x, y, theta) standing; noise on, seeded.
  // `cfg` configures its Motion module (Programs::setMotionConfig).
  explicit MotionHarness(uint64_t seed = 1, double x = -3.0, double y = 0.0, double theta = 0.0,
                         const std::string& extra_yaml = "",
                         const agent::motion::MotionConfig& cfg = agent::motion::MotionConfig())
      : runner_(makeScenario(seed, x, y, theta, extra_yaml)) {
    auto b = std::make_unique<agent::behaviour::RequestedBehaviour>();
    mailbox_ = b->mailbox();
    runner_.programs().setBehaviour(0, std::move(b));
    runner_.programs().setMotionConfig(0, cfg);
    runner_.programs().setThreading(agent::program::Threading::Inline);  // deterministic, no hand-over
    runner_.start();
    auto* m = dynamic_cast<agent::program::MotionThreadModule*>(
        runner_.programs().program(0)->schedule().find("motion"));
    if (!m) throw std::logic_error("motion_test: the robot program runs no Motion module");
    motion_ = &m->motion();
  }

  static simswift::runner::Scenario makeScenario(uint64_t seed, double x, double y, double theta,
                                                 const std::string& extra) {
    const std::string yaml = "duration: 1000\nseed: " + std::to_string(seed) +
                             "\nnoise: on\nrobots:\n  - {team: 0, player: 1, x: " + std::to_string(x) +
                             ", y: " + std::to_string(y) + ", theta: " + std::to_string(theta) +
                             ", posture: stand}\n" + extra;
    simswift::runner::Scenario sc = simswift::runner::Scenario::parse(yaml, "motion_test");
    return sc;
  }

  void request(agent::blackboard::ActionType type, double forward = 0, double left = 0, double turn = 0) {
    mailbox_->set([&](agent::blackboard::MotionRequest& r) {
      r.body.type = type;
      r.body.forward = static_cast<float>(forward);
      r.body.left = static_cast<float>(left);
      r.body.turn = static_cast<float>(turn);
      ++r.sequence;
    });
  }
  void kick(agent::blackboard::Foot foot, double power, double direction = 0) {
    mailbox_->set([&](agent::blackboard::MotionRequest& r) {
      r.body.type = agent::blackboard::ActionType::KICK;
      r.body.foot = foot;
      r.body.kick_power = static_cast<float>(power);
      r.body.kick_direction = static_cast<float>(direction);
      ++r.sequence;
    });
  }

  // Ticks for `seconds` of simulated time; returns false if the robot fell.
  bool run(double seconds) {
    const int64_t n = runner_.world().ticksIn(seconds);  // the robot's body's tick
    bool ok = true;
    for (int64_t i = 0; i < n; ++i) {
      runner_.tick();
      checked_.check(runner_.lastCommand(0), runner_.lastSensors(0));
      if (torsoHeight() < simswift::runner::FallDetector::kFallHeight) ok = false;
    }
    return ok;
  }

  // Torso pose projected on the ground (field frame).
  Pose2 pose() {
    const Eigen::Isometry3d t = runner_.world().robot(0).linkPose(runner_.world().robot(0).model().rootLink());
    const Eigen::Vector3d x = t.rotation().col(0);
    return {t.translation().x(), t.translation().y(), std::atan2(x.y(), x.x())};
  }
  double torsoHeight() {
    return runner_.world().robot(0).linkPose(runner_.world().robot(0).model().rootLink()).translation().z();
  }

  // The program's Motion section after the last tick (its Blackboard).
  agent::blackboard::MotionState state() const { return runner_.programs().program(0)->board().motion.read(); }
  // The program's Motion module (its MotionThreadModule's), for what the
  // Motion section does not publish: mode(), getupAttempts(). Read between ticks.
  const agent::motion::ActionMotion& motion() const { return *motion_; }
  simswift::runner::Runner& runner() { return runner_; }
  // The limit checks over every tick so far, the last command and sensors.
  const CommandCheck& checked() const { return checked_; }

  // A push: adds `dv` (m/s, field frame) to the torso's velocity.
  void push(double vx, double vy) {
    dBodyID b = runner_.world().robot(0).torsoBody();
    const dReal* v = dBodyGetLinearVel(b);
    dBodySetLinearVel(b, v[0] + vx, v[1] + vy, v[2]);
  }

 private:
  simswift::runner::Runner runner_;
  std::shared_ptr<agent::behaviour::MotionRequestMailbox> mailbox_;
  const agent::motion::ActionMotion* motion_ = nullptr;
  CommandCheck checked_;
};

inline double wrapAngle(double a) { return std::atan2(std::sin(a), std::cos(a)); }

}  // namespace motion_test
