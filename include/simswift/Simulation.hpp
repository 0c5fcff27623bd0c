// simswift as a library: a simulation built once from a scenario, stepped
// one 10 ms tick at a time, in the spirit of MuJoCo's mj_step. Each step()
// runs the runner's tick stages in their one documented order (commands to
// the servos, pushes, physics, sensors, every robot program's answer, ...:
// sim/runner/Runner.hpp in the source tree), so a unit test here gets the
// same physics, in lock-step, as `simswift run` and every other mode.
//
//   simswift::Simulation sim = simswift::Simulation::fromScenario("walk_one.yaml");
//   sim.robot(0).setController([&](const simswift::SensorValues& s, simswift::JointValues& j) {
//     myWalk.tick(s, j);   // the team's own Motion, called each tick on this thread
//   });
//   sim.run(5.0);
//   EXPECT_GT(sim.robot(0).pose().x, 0.5);
//
// Robots without a controller run what their scenario says (the builtin
// reference program, a launched program, ...). Errors: ConfigError
// (Errors.hpp: a bad scenario, model or field: file, line, key),
// std::logic_error (misuse, e.g. a controller set after the first step),
// std::runtime_error (a run that fails).
//
// Before the first step every call is valid: the queries answer from the
// scenario and start nothing (time 0, ticks 0, pose and ball as placed,
// fallen false, falls 0, stateHash 0), except sensors(), which exist only
// once a tick has run (std::logic_error); placeBall, push and teleport
// start the simulation as step() does. A start that fails (a missing model:
// ConfigError) fails the same way on every later call.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include "simswift/Errors.hpp"
#include "simswift/Types.hpp"

namespace simswift::api {

// Called once per tick on the simulator's thread with the sensors of this
// tick; `joints` arrives holding the previous command and is sent as this
// tick's (acting during the next tick, as on the NAO).
using Controller = std::function<void(const SensorValues& sensors, JointValues& joints)>;

// libagent beyond the sensors and joints, as an external program sees it in
// the block (docs/libagent.md). In: `standing`, libagent's one-shot "just
// stiffened" flag (set at a stiff start until the first command, and on
// every limp-to-stiff change; this tick's command clears it, as rUNSWift's
// Effector does; while it is set the body gets libagent's sit at stiffness
// 0), and `buttons`, the ButtonPresses (bit n-1: a series of n chest clicks
// ended; libagent keeps 2, 3 and 4 clicks). Out: `stiffen`, send STIFFEN
// with this tick's command (a limp body stiffens and `standing` is set).
struct Libagent {
  bool standing = false;
  uint8_t buttons = 0;
  bool stiffen = false;  // reset to false every tick
};
using LibagentController = std::function<void(const SensorValues& sensors, JointValues& joints, Libagent& libagent)>;

class Simulation;
struct SimulationAccess;  // the library's own helpers (app/api), e.g. the walk test kit

// A handle to robot i of a Simulation (valid while it lives).
class Robot {
 public:
  int index() const { return index_; }
  // The sensors its program read this tick (the libagent block's slot);
  // std::logic_error before the first step.
  SensorValues sensors() const;
  // Before the first step: drive this robot from `c` instead of its
  // scenario program.
  void setController(Controller c);
  // The same, seeing `standing` and the buttons and able to send STIFFEN
  // (a team's MotionAdapter resets its generators while `standing` is set).
  void setController(LibagentController c);
  // Hold these joint commands (a controller that repeats them); before the
  // first step, or later for a robot already driven by setJoints.
  void setJoints(const JointValues& joints);
  Pose pose() const;         // ground truth, field frame (before the first step: as placed, z 0)
  bool fallen() const;       // on the ground now (the runner's fall detector)
  int falls() const;         // falls so far
  void push(double jx, double jy);  // impulse N*s at the torso's centre of mass (field axes), now
  void teleport(double x, double y, double theta);  // standing, at rest

 private:
  friend class Simulation;
  Robot(Simulation* sim, int index) : sim_(sim), index_(index) {}
  Simulation* sim_;
  int index_;
};

class Simulation {
 public:
  // From a scenario file, or YAML text (`name` for errors; relative paths
  // resolve against `base_dir`, default the working folder). Throws ConfigError.
  static Simulation fromScenario(const std::string& path);
  static Simulation fromYaml(const std::string& text, const std::string& name = "<yaml>",
                             const std::string& base_dir = ".");
  Simulation(Simulation&&) noexcept;
  Simulation& operator=(Simulation&&) noexcept;
  ~Simulation();

  void step();  // one 10 ms tick (the first builds the world and starts the programs)
  // Steps for `seconds` of simulated time, or until `until` (checked after
  // each tick) returns true. Returns the simulated seconds stepped.
  double run(double seconds, const std::function<bool(const Simulation&)>& until = {});

  double time() const;     // s of simulated time
  int64_t ticks() const;
  int numRobots() const;
  Robot robot(int i);      // throws std::out_of_range
  BallState ball() const;              // before the first step: as placed, at rest
  void placeBall(double x, double y);  // at rest on the carpet, m
  uint64_t stateHash() const;          // the World's (the same as `simswift run --print-hash-every`); 0 before the first step
  double duration() const;             // the scenario's duration, s

  // Records the run from the next step on as MCAP (docs/recording.md: the
  // links' and the ball's poses, joints, sensors, events, team messages),
  // rate_hz samples per simulated second (0 < rate_hz <= 1000). The file is
  // complete once finishRecording() runs or the Simulation goes. Throws
  // std::runtime_error if the file cannot be written, std::logic_error if a
  // recording is already running, std::invalid_argument for a bad rate.
  void record(const std::string& path, double rate_hz = 20);
  // Writes the recording's index and closes it (nothing if none runs).
  void finishRecording();

 private:
  friend class Robot;
  friend struct SimulationAccess;
  struct Impl;
  explicit Simulation(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace simswift::api

// The names a test writes (simswift::Simulation, simswift::SensorValues, ...).
namespace simswift {
using api::BallState;
using api::Controller;
using api::JointValues;
using api::Libagent;
using api::LibagentController;
using api::Pose;
using api::Robot;
using api::SensorValues;
using api::Simulation;
}  // namespace simswift
