// A walk test kit: command a team's gait, measure what it achieves from the
// true pose, count falls, record a per-tick trace and plot it.
//
//   TEST(MyWalk, Reaches90PercentOf200ForwardOverTwentySeeds) {
//     for (uint64_t seed = 1; seed <= 20; ++seed) {
//       MyWalk walk;   // the team's walk, fresh per seed
//       simswift::WalkTest test(seed, [&](const simswift::WalkCommand& c, const simswift::SensorValues& s,
//                                         simswift::JointValues& j) { walk.tick(c, s, j); });
//       const simswift::WalkFigures f = test.walk({200, 0, 0});   // 2 s to start, 6 s measured
//       EXPECT_GE(f.forward_ratio, 0.9) << f.summary();
//       EXPECT_EQ(f.falls, 0) << f.summary();
//     }
//   }
//
// The gait runs through Robot::setController (the libagent block, the same
// tick stage as any robot program). The figures come from WalkMeter, the one
// home of these measurements: simswift's own motion benchmark
// (bench_motion) measures the reference walk with it too.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>

#include "simswift/Simulation.hpp"
#include "simswift/Types.hpp"

namespace simswift::api {

// A walk command in rUNSWift's walk-request units: forward and left in mm/s
// (robot frame: x ahead, y to the left), turn in rad/s (anticlockwise seen
// from above positive). walk = false asks the gait to stand.
struct WalkCommand {
  double forward = 0;  // mm/s
  double left = 0;     // mm/s
  double turn = 0;     // rad/s
  bool walk = true;
  // s: the robot's tick, filled in by the kit before each call of the gait
  // (10 ms on a V5 over libagent, 12 ms on a V6 over LoLA): the time a
  // gait steps by. Whatever the caller sets here is overwritten.
  double tick = 0;
};

// The team's gait: called once per tick (command.tick) with the command in force, the
// sensors of this tick, and the joint command to fill (it arrives holding
// the previous tick's, as a Controller's).
using Gait = std::function<void(const WalkCommand& command, const SensorValues& sensors, JointValues& joints)>;

// One foot's ground truth at a tick.
struct FootTruth {
  double x = 0, y = 0;  // the middle of the sole, field frame, m
  double force = 0;     // vertical ground reaction on the foot, N
};

// One tick of ground truth (what the meter reads; WalkTest::sample()).
struct WalkSample {
  double t = 0;        // s of simulated time
  Pose torso;          // true torso pose, field frame
  int falls = 0;       // falls so far (the simulator's fall detector: torso origin below 0.20 m)
  FootTruth feet[2];   // left, right
};

// What a walk achieved over one measured window.
struct WalkFigures {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  WalkCommand commanded;
  double seconds = 0;  // the window, s
  // Achieved: the torso's displacement over the window in the heading frame
  // at its start (forward, left: mm/s) and its unwrapped heading change (turn: rad/s).
  double forward = 0, left = 0, turn = 0;
  // Achieved / commanded per direction; NaN where that direction's command is 0.
  double forward_ratio = kNone, left_ratio = kNone, turn_ratio = kNone;
  // Least-squares slope of the heading change over the window (rad/s): the
  // drift of a walk asked not to turn, steadier than end minus start (the
  // torso yaws back and forth within each step).
  double heading_slope = 0;
  int falls = 0;    // falls during the measurement (WalkTest::walk: the start included)
  // Stance slip: a foot is in stance while it carries more than 70 % of the
  // feet's vertical force (and they carry more than 10 N); a stance's slip is
  // the largest horizontal distance its sole centre moves from where the
  // stance began. Over the stances completed in the window.
  int stances = 0;
  double slip_mean = 0, slip_max = 0;  // mm per stance
  // One line: "forward 200 mm/s: 194 mm/s (0.97) | ... | falls 0 | slip mean 0.4 max 1.2 mm (23 stances)".
  std::string summary() const;
};

// The measurement: begin() at the start of the window, add() after every
// tick, figures() at any time. Plain samples, so any driver can feed it.
class WalkMeter {
 public:
  void begin(const WalkSample& start, const WalkCommand& commanded);
  void add(const WalkSample& s);
  WalkFigures figures() const;

 private:
  WalkCommand commanded_;
  WalkSample start_, last_;
  double turned_ = 0;                          // rad, unwrapped heading change since start
  double n_ = 0, st_ = 0, sy_ = 0, stt_ = 0, sty_ = 0;  // heading least-squares sums
  bool stance_[2] = {false, false};
  double stance_x_[2] = {0, 0}, stance_y_[2] = {0, 0}, worst_[2] = {0, 0};  // m
  int stances_ = 0;
  double slip_sum_ = 0, slip_max_ = 0;  // m
  bool begun_ = false;
};

// Where the robot starts and what the world holds: one robot, no ball.
struct WalkTestSetup {
  uint64_t seed = 1;
  bool noise = true;
  // Field frame, m / rad: the own goal area facing the far goal (6 m ahead).
  double x = -3.0, y = 0.0, theta = 0.0;
};

// A simulation with one robot driven by a gait. Step it through run() or
// walk() (stepping the Simulation directly bypasses the trace).
class WalkTest {
 public:
  WalkTest(uint64_t seed, Gait gait);
  WalkTest(const WalkTestSetup& setup, Gait gait);
  // The team's own simulation; the gait drives robot `robot` (before the first step).
  WalkTest(Simulation sim, int robot, Gait gait);
  WalkTest(WalkTest&&) noexcept;
  WalkTest& operator=(WalkTest&&) noexcept;
  ~WalkTest();

  // The command from the next tick on.
  void command(const WalkCommand& c);
  WalkCommand command() const;
  // Steps `seconds` of simulated time (a trace gets a row per tick).
  void run(double seconds);
  // Commands `c`, runs `settle` s for the gait to reach speed, then measures
  // `window` s. falls: from the command on. The defaults are bench_motion's.
  WalkFigures walk(const WalkCommand& c, double settle = 2.0, double window = 6.0);

  // Records a CSV row per tick from now on (over-writes `csv_path`; throws
  // std::runtime_error if it cannot be written). Columns: see docs/library.md.
  void trace(const std::string& csv_path);
  void stopTrace();  // flushes and closes it

  WalkSample sample() const;  // ground truth now
  Simulation& simulation();
  Robot robot();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Plots a trace CSV to a PNG with gnuplot (pose, heading, leg joints
// commanded against measured, FSR sums, gyroscope). False with *message if
// gnuplot is missing or fails; the data and script stay beside the PNG.
bool plotTrace(const std::string& csv_path, const std::string& png_path, std::string* message = nullptr);

// simswift's reference walk (its robot code's Walk2014Generator, gains as
// shipped) as a Gait: a yardstick for a team's own under the same test.
// Each call makes a fresh walk; copies of one Gait share its walk state, so
// give each WalkTest its own referenceGait().
Gait referenceGait();

}  // namespace simswift::api

namespace simswift {
using api::FootTruth;
using api::Gait;
using api::WalkCommand;
using api::WalkFigures;
using api::WalkMeter;
using api::WalkSample;
using api::WalkTest;
using api::WalkTestSetup;
using api::plotTrace;
using api::referenceGait;
}  // namespace simswift
