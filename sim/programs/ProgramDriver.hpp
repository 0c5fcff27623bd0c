// The seam between the simulator and the robot program: one interface for
// whatever drives a robot's body (the model: MuJoCo's mjcb_control, the
// callback that computes a body's controls each step, and SimRobot's device
// boundary). The Runner sees a robot program only through it; every
// implementation and their factory (Programs.hpp) live in sim/programs
// (which includes nothing of sim/runner: the Runner builds on it), the
// only folder of sim/ that may include the robot program (agent/program,
// behaviour, motion, blackboard, ...; configure refuses a direct include
// anywhere else: docs/architecture.md says what it does not yet catch).
//
// Each tick the body side posts the robot's sensors (sim/bridge/BodySide.hpp)
// and the Runner asks the driver for the answer; each camera frame the same
// with the frame. The five implementations:
//   ThreadedProgram   builtin, on its own named Motion and Perception threads
//   InlineProgram     builtin, its steps run on the simulator's thread
//   ApiController     the public API's controller as an inline program's Motion step
//   ExternalProgram   a program started by hand, attached by name
//   LaunchedProgram   a program simswift starts itself (program: {command})
#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include "sim/views/FindBallView.hpp"

namespace simswift::bridge {
class BodySide;
}

namespace simswift::programs {

// One robot as its program driver sees it (built by the Runner with the bodies).
struct RobotSlot {
  int index = 0;                     // scenario order
  std::string tag;                   // "t19p2"
  int player = 0;                    // its player number (the FindBall view names it)
  bridge::BodySide* host = nullptr;  // its body side (libagent's BodyHost, LoLA's LolaBody)
};

// What a builtin robot program believes, for observers (the recording's
// /robot<i>/belief, docs/recording.md): field frame, m and rad.
struct Belief {
  bool ball_known = false;         // its ball estimate (its own, else its team's) holds a ball
  double ball_x = 0, ball_y = 0;   // m
  double x = 0, y = 0, theta = 0;  // its localisation's pose: m, m, rad
  std::string behaviour;           // what its behaviour does now ("findball2017", "penalised", ...; "" none)
};

class ProgramDriver {
 public:
  enum class Step { Motion, Perception };  // a tick, a camera frame

  virtual ~ProgramDriver() = default;
  ProgramDriver(const ProgramDriver&) = delete;
  ProgramDriver& operator=(const ProgramDriver&) = delete;

  // The first attach (tick stage 7 of the robot's first tick). True: this
  // waited for the program's first answer itself (an external program, up
  // to the scenario's attach_timeout, wall clock; throws RunnerError or
  // ProgramError if none came); false: the first tick is answered as every
  // other (a builtin program is there from the start).
  virtual bool attach() { return false; }
  // The body side has posted a tick or a camera frame: a program that runs
  // on the simulator's thread takes its step now (tick: for messages).
  // Throws WatchdogError if that step fails.
  virtual void posted(Step /*step*/, int64_t /*tick*/) {}
  // Tick `tick`'s simulated time for a program in another process (its
  // clock page, docs/shim.md), written before the tick's sensors are posted
  // (Runner stage 6). Nothing for a builtin program (it reads the tick).
  virtual void publishTime(int64_t /*tick*/) {}
  // Waits up to timeout_s (wall clock) for the answer to what was posted;
  // false on timeout. Throws ProgramError if a launched program ended.
  virtual bool await(Step step, double timeout_s);
  // Throws ProgramError if a launched program has ended (for a wait the
  // driver does not do itself: its cameras' lock-step, between slices).
  virtual void checkRunning() {}
  // Why the program went silent, for the watchdog's message (a builtin
  // thread's exception); empty if not known.
  virtual std::string error() const { return {}; }
  // After the body side's shutdown: a launched program is stopped
  // (SIGTERM, then SIGKILL after its stop_grace) and reaped.
  virtual void stop() {}
  // After every driver's stop(): builtin threads joined. The program stays
  // readable until the driver goes.
  virtual void join() {}
  // Its log file ("t19p2: simswift-logs/t19p2.log"); empty if none.
  virtual std::string log() const { return {}; }
  // A launched program's wlan0 (a TAP descriptor, handed over once, the
  // caller owns it: sim/programs/RobotNetwork.hpp); -1 for every other.
  virtual int takeNetwork() { return -1; }
  // The observer hook: the robot's FindBall search as the FindBall view
  // draws it (what the robot itself believes), filled by the program side
  // between ticks. False: nothing to show (no search published).
  virtual bool findBallView(sim::views::FindBallViewData& /*out*/) const { return false; }
  // The observer hook for what the program believes (its ball estimate,
  // its pose, its behaviour's state), between ticks. False: not known (a
  // program simswift does not compose).
  virtual bool belief(Belief& /*out*/) const { return false; }

  const RobotSlot& slot() const { return slot_; }

 protected:
  explicit ProgramDriver(RobotSlot slot) : slot_(std::move(slot)) {}
  RobotSlot slot_;
};

}  // namespace simswift::programs
