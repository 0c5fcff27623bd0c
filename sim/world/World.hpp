// The ODE world: field, ball, robots, contacts, fixed-step stepping and the
// state hash. One world, single-threaded. `step()` advances one tick
// (WorldConfig::tick_us: 10 ms on the V5, 12 ms on the V6) made of a whole
// number of substeps; its order is fixed and commented in World.cpp.
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <cmath>

#include "common/nao/NaoFacts.hpp"
#include "sim/nao_model/RobotModel.hpp"
#include "sim/nao_model/RobotBody.hpp"
#include "sim/world/FieldConfig.hpp"

namespace simswift {

// s: the NAO V5's DCM / Motion cycle, WorldConfig::tick_us's default (a
// V6 world ticks at LoLA's 12 ms: sim/runner/Bodies.hpp).
constexpr double kTickSeconds = common::nao::kMotionTickSeconds;

struct WorldConfig {
  enum class Solver { Exact, Quick };
  Solver solver = Solver::Quick;     // why (measured): docs/world.md, "Measurements"
  // us per tick: the robots' cycle, their body interface's (libagent on the
  // V5 10 ms, LoLA on the V6 12 ms; sim/runner/Bodies.hpp bodyCycleUs).
  int64_t tick_us = common::nao::kMotionTickUs;
  // Physics steps per tick. 0: the fewest that keep each step within
  // max_substep_us (a 10 ms tick: 2 x 5 ms; the V6's 12 ms: 3 x 4 ms); a
  // positive count is taken as given (a scenario's `physics: {substeps}`).
  // Every setting here was measured with 5 ms steps (docs/world.md), and
  // QuickStep's residual at its 20 iterations grows with the step: 2 x 6 ms
  // tipped pushed-over V6s and V5s back at the end of their get-ups, and
  // some V6s fell (docs/world.md, "Step length").
  int substeps = 0;
  int64_t max_substep_us = 5000;     // us
  int substepsPerTick() const {
    return substeps > 0 ? substeps : static_cast<int>((tick_us + max_substep_us - 1) / max_substep_us);
  }
  int quick_iterations = 20;
  double quick_w = 1.7;              // QuickStep's over-relaxation (ODE's default 1.3), see docs/world.md
  double erp = 0.8;
  double cfm = 1e-5;
  // After each substep, up to this many Gauss-Seidel sweeps move each
  // robot's links until its hinge anchors are within the tolerance
  // (JointProjector; docs/world.md says why). 0 turns it off.
  int joint_projection_sweeps = 16;
  double joint_projection_tolerance = 1e-4;  // m
  double gravity = 9.81;             // m/s^2
  double blowup_linear_speed = 50;   // m/s: beyond this a body has blown up
  double blowup_angular_speed = 200; // rad/s
  // m: a body farther than this from the centre spot (or higher) has blown
  // up; placements beyond it are refused.
  double max_distance = 1000;
  // The sole on the carpet (Contacts.cpp): a grid of sole_nx x sole_ny
  // points over the sole box's bottom face (corners included), each a
  // damped spring; together the sole's vertical stiffness and damping.
  int sole_nx = 4, sole_ny = 3;
  static constexpr int kMaxSolePoints = 64;  // sole_nx x sole_ny at most (Contacts.cpp's per-sole arrays)
  double sole_stiffness = 2.0e5;     // N/m, whole sole: 52 N (the NAO) sinks 0.26 mm
  double sole_damping = 2.0e3;       // N*s/m, whole sole: about critical for 5.3 kg
  // Static friction that holds (Contacts.cpp): each sole point in contact
  // remembers where it touched down (m, world xy); the friction rows are
  // asked to remove this fraction of the drift from it per substep, within
  // the friction cone, as the joints' ERP does for their anchors. A point
  // that drifts farther than sole_anchor_slip really slides: it re-anchors
  // where it is. 0 turns the anchors off.
  double sole_anchor_erp = 0.2;
  double sole_anchor_slip = 0.005;   // m
  ServoConfig servo;
};

// The first value of `c` that breaks its rule: the field (named as in the
// struct) and why ("must be in [1, 100] (got 0)"). The one home of the
// rules: World's constructor refuses such a config (ConfigError "world:
// field: why"), and the scenario's physics: reader (sim/runner/Scenario.cpp)
// refuses it naming the file, line and key. Fields without a rule (gravity,
// the blow-up limits, servo) are taken as given.
struct WorldConfigProblem {
  std::string field, why;
};
std::optional<WorldConfigProblem> checkWorldConfig(const WorldConfig& c);

// A contact felt by a robot link during the last tick, averaged over its
// substeps: the force the environment exerts on the link (N, world frame) at
// `position` (m, world frame). contacts() holds one entry per contact point
// per substep with the force already divided by the number of substeps, so
// summing a link's entries gives its tick-average force.
struct LinkContact {
  int robot;
  int link;
  GeomTag::Kind other;
  int other_robot;  // if other == RobotLink
  Eigen::Vector3d position;
  Eigen::Vector3d force;
};

// A value the World refuses (placement far outside the world, a NaN, an
// absurd push): thrown before anything reaches ODE.
struct WorldError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct WorldEvent {
  enum class Kind { BlowUp } kind;
  int64_t tick;
  int robot;            // -1 for the ball
  std::string message;
};

class World {
 public:
  World(const FieldConfig& field, const WorldConfig& config = {});
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Adds a robot (any RobotModel: the NAO, a box, a pendulum) whose lowest
  // collision shape rests on the carpet (the NAO: its feet) with its root
  // link at (x, y) m facing `theta` rad, joints at `posture` (model joint
  // order). Returns its index.
  int addRobot(std::shared_ptr<const RobotModel> model, double x, double y, double theta,
               const std::vector<double>& posture);
  int numRobots() const { return static_cast<int>(robots_.size()); }
  RobotBody& robot(int i) { return *robots_[i]; }
  const RobotBody& robot(int i) const { return *robots_[i]; }

  // Teleports: velocities zeroed. A robot is re-seated on its feet.
  // Positions must be finite and within config().max_distance (WorldError).
  void placeRobot(int i, double x, double y, double theta, const std::vector<double>& posture);
  void placeBall(double x, double y);
  // Takes the ball out of the world for good (a scenario's `ball: none`):
  // its body and geom are disabled (no contacts, no motion) and hasBall()
  // is false, so vision, cameras and views show no ball. placeBall() after
  // this throws WorldError.
  void removeBall();
  bool hasBall() const;
  void setBallVelocity(const Eigen::Vector3d& v);  // m/s, world; |v| <= blowup_linear_speed

  // A push: an impulse of `impulse` N*s (world frame) at the torso's centre
  // of mass, delivered as a constant force over the first substep of the
  // next step(). The robot's momentum changes by exactly `impulse`: the
  // whole robot's CoM velocity by impulse / total mass (5.3 kg NAO: 1 N*s
  // gives 0.19 m/s), the torso more at first as the joints pass it on.
  // |impulse| <= kMaxPushImpulse (WorldError otherwise).
  static constexpr double kMaxPushImpulse = 50.0;  // N*s: ~9 m/s for a NAO
  void applyImpulse(int robot, const Eigen::Vector3d& impulse);
  Eigen::Vector3d ballPosition() const;
  Eigen::Vector3d ballVelocity() const;
  // The ball body's orientation (world frame); drawn by the cameras.
  Eigen::Quaterniond ballOrientation() const;

  // Advances one tick (tickUs()). Detects blow-ups before every substep and after
  // the last (NaN/inf, speed beyond the limits, farther than max_distance),
  // before ODE can reach a state it aborts on: the robot (or ball) is reset
  // to where it was last placed and an event is recorded; the run goes on.
  void step();
  // Steps the physics `ticks` ticks without counting them (tick() and
  // time() stay): the robots, their servos holding what they were last
  // commanded, come to rest where they were placed before anyone reads
  // them (Runner::start; issue 45: the first packet showed a robot still
  // sinking into its contacts). Deterministic: its own ODE seeds.
  void settle(int ticks);
  int64_t tick() const { return tick_; }
  double time() const { return tick_ * tickSeconds(); }  // s
  int64_t tickUs() const { return config_.tick_us; }    // us per tick (WorldConfig::tick_us)
  double tickSeconds() const { return config_.tick_us * 1e-6; }
  int substeps() const { return config_.substepsPerTick(); }  // physics steps per tick
  // Ticks in `seconds` of simulated time (rounded to the nearest).
  int64_t ticksIn(double seconds) const { return common::nao::ticksIn(seconds, config_.tick_us); }

  const std::vector<LinkContact>& contacts() const { return contacts_; }
  std::vector<WorldEvent> takeEvents();

  // Distance (m) from `origin` along unit `dir` to the first geom hit within
  // `max_range`, ignoring robot `ignore_robot`'s own links; < 0 if none.
  double rayCast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double max_range,
                 int ignore_robot) const;

  // FNV-1a over every body's pose and velocities (bit patterns), in a fixed
  // order: ball, then robots by index, links by model index.
  uint64_t stateHash() const;

  const FieldConfig& field() const { return field_; }
  const WorldConfig& config() const { return config_; }
  dWorldID odeWorld() const { return world_; }
  dBodyID ballBody() const;  // for tests that must reach past the API

 private:
  // Stages of step() (World.cpp gives the order).
  void checkBlowUps();
  void applyPendingPushes(double dt);
  void stepPhysics(int64_t seed_tick);  // one tick's substeps; ODE seeded from seed_tick
  void integrate(int64_t seed_tick, int substep, double dt);
  void projectJoints();
  void checkPlacement(const char* what, double x, double y, double theta) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  FieldConfig field_;
  WorldConfig config_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  std::vector<std::unique_ptr<RobotBody>> robots_;
  std::vector<LinkContact> contacts_;
  std::vector<WorldEvent> events_;
  int64_t tick_ = 0;
};

}  // namespace simswift
