// Shared harness for the Motion physics tests: one robot in the lock-step
// runner with the MotionModule as its Motion thread; the test plays
// Behaviour by setting the motion request between ticks (RequestedMotion).
// Units: m and rad in the field frame (world), mm in the robot frame (odometry).
#pragma once

#include <cmath>
#include <memory>
#include <string>

#include "agent/blackboard/Blackboard.hpp"
#include "agent/motion/RequestedMotion.hpp"
#include "sim/runner/Runner.hpp"

namespace motion_test {

// Down or on the way up: the postures a pushed-over robot passes through.
inline bool downOrGettingUp(agent::blackboard::BodyState p) {
  using P = agent::blackboard::BodyState;
  return p == P::FALLEN_FORWARD || p == P::FALLEN_BACKWARD || p == P::FALLEN_SIDEWAYS || p == P::GETTING_UP;
}

// Forwards to the MotionModule and checks every command it sends against the
// joint limits and the per-tick speed limit (the clipper's promise).
class CheckedMotion : public agent::framework::MotionGenerator {
 public:
  explicit CheckedMotion(std::unique_ptr<agent::motion::RequestedMotion> m) : m_(std::move(m)) {}
  void tick(const agent::libagent::SensorValues& s, int64_t t_us, agent::libagent::JointValues& out) override {
    m_->tick(s, t_us, out);
    last_command = out;
    last_sensed = s;
    const auto& lim = agent::motion::jointLimits();
    for (int i = 0; i < agent::libagent::kNumJoints; ++i) {
      const float a = out.angles[i];
      if (!(a >= lim[i].lower && a <= lim[i].upper)) ++limit_violations;
      if (have_prev_ && std::fabs(a - prev_[i]) > lim[i].max_velocity * agent::motion::kMotionTick + 1e-6)
        ++speed_violations;
      prev_[i] = a;
    }
    have_prev_ = true;
    ++ticks;
  }
  agent::motion::RequestedMotion& motion() { return *m_; }
  int64_t limit_violations = 0, speed_violations = 0, ticks = 0;
  agent::libagent::JointValues last_command{};
  agent::libagent::SensorValues last_sensed{};

 private:
  std::unique_ptr<agent::motion::RequestedMotion> m_;
  float prev_[agent::libagent::kNumJoints] = {};
  bool have_prev_ = false;
};

struct Pose2 {
  double x, y, theta;  // m, m, rad (field frame)
};

class MotionHarness {
 public:
  // A scenario with one robot at (x, y, theta) standing; noise on, seeded.
  explicit MotionHarness(uint64_t seed = 1, double x = -3.0, double y = 0.0, double theta = 0.0,
                         const std::string& extra_yaml = "",
                         const agent::motion::MotionConfig& cfg = agent::motion::MotionConfig())
      : runner_(makeScenario(seed, x, y, theta, extra_yaml)) {
    auto m = std::make_unique<agent::motion::RequestedMotion>(cfg);
    motion_ = m.get();
    auto c = std::make_unique<CheckedMotion>(std::move(m));
    checked_ = c.get();
    runner_.setMotionGenerator(0, std::move(c));
    runner_.start();
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
    motion_->request([&](agent::blackboard::MotionRequest& r) {
      r.body.type = type;
      r.body.forward = static_cast<float>(forward);
      r.body.left = static_cast<float>(left);
      r.body.turn = static_cast<float>(turn);
      ++r.sequence;
    });
  }
  void kick(agent::blackboard::Foot foot, double power, double direction = 0) {
    motion_->request([&](agent::blackboard::MotionRequest& r) {
      r.body.type = agent::blackboard::ActionType::KICK;
      r.body.foot = foot;
      r.body.kick_power = static_cast<float>(power);
      r.body.kick_direction = static_cast<float>(direction);
      ++r.sequence;
    });
  }

  // Ticks for `seconds` of simulated time; returns false if the robot fell.
  bool run(double seconds) {
    const int n = static_cast<int>(std::lround(seconds / simswift::kTickSeconds));
    bool ok = true;
    for (int i = 0; i < n; ++i) {
      runner_.tick();
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

  agent::blackboard::MotionState state() const { return motion_->state(); }
  agent::motion::MotionModule& motion() { return motion_->module(); }
  simswift::runner::Runner& runner() { return runner_; }

 private:
  simswift::runner::Runner runner_;
  agent::motion::RequestedMotion* motion_ = nullptr;
  CheckedMotion* checked_ = nullptr;

 public:
  const CheckedMotion& checked() const { return *checked_; }

  // A push: adds `dv` (m/s, field frame) to the torso's velocity.
  void push(double vx, double vy) {
    dBodyID b = runner_.world().robot(0).torsoBody();
    const dReal* v = dBodyGetLinearVel(b);
    dBodySetLinearVel(b, v[0] + vx, v[1] + vy, v[2]);
  }
};

inline double wrapAngle(double a) { return std::atan2(std::sin(a), std::cos(a)); }

}  // namespace motion_test
