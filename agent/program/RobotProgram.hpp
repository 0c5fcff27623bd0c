// A robot program: the robot code's threads around one body connection
// (BodyConnection.hpp: libagent's block on a V5, LoLA's socket on a V6), its
// Blackboard, and the modules each thread runs (ordered in ModuleOrder.cpp).
//
//   Motion     (thread "t<T>p<P>-motion"):  loop { waitTick; readSensors ->
//              sensors section; motion -> effector; writeActuators
//              (sets actuators_latest: the answer the body side waits for) }
//   Perception (thread "t<T>p<P>-percept"): loop { wait frame_ready; frame
//              (+ the sensors of the tick just done) -> frame section, the
//              game-state block -> game_controller, arrived team packets ->
//              team_inbox; game state -> vision adapter -> localisation ->
//              ball tracker -> team receive -> behaviour -> team send;
//              team_outbox -> the team transport; post perception_done }
//
// Two ways to run the same steps (the same order, the same results: the
// same state hash, tested):
//   Threading::Named   the two threads above, each blocking on its wake-up
//                      (gdb sees them by name; an external program's way)
//   Threading::Inline  no threads: the simulator calls stepMotion() /
//                      stepPerception() on its own thread right after it
//                      posts the tick / frame (no hand-over between threads:
//                      experiments and benchmarks)
// start() checks the modules' declared reads and writes first: a module
// reading a section nobody provides throws ModuleError naming both.
// Robot code sees simulated time only (the sensor slot's time in the
// extension object). The threads end when the body side sets shutdown and
// wakes them, or when a simulator attached by name has gone.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "agent/blackboard/Blackboard.hpp"
#include "agent/comms/TeamTransport.hpp"
#include "common/libagent/AgentConnection.hpp"
#include "agent/program/BodyConnection.hpp"
#include "agent/program/ModuleOrder.hpp"
#include "agent/framework/ModuleSchedule.hpp"

namespace agent::program {

enum class Threading { Named, Inline };

// libagent beyond the joints, for a Motion step that wants it (the public
// API's libagent controller). rUNSWift's Touch reads the block's `standing`
// and the slot's ButtonPresses with the sensors, and its Effector may send
// STIFFEN with a command: the program fills the first two before each
// Motion step and sends `stiffen` (reset to false each step) with its command.
struct LibagentIO {
  bool standing = false;  // the block's flag when the sensors were read
  uint8_t buttons = 0;    // ButtonPresses of the slot read (bit n-1: a series of n chest clicks)
  bool stiffen = false;   // set by the step: STIFFEN with this command
};

class RobotProgram {
 public:
  // The standard modules; `cfg` says which motion and behaviour.
  RobotProgram(std::unique_ptr<BodyConnection> connection, ProgramConfig cfg);
  // On libagent's block (libagentBody).
  RobotProgram(common::libagent::AgentConnection connection, ProgramConfig cfg);
  // Shorthand: a MotionGenerator for Motion, no behaviour, an optional
  // PerceptionStep run first in the Perception thread.
  RobotProgram(common::libagent::AgentConnection connection, int team, int player,
               std::unique_ptr<framework::MotionGenerator> motion,
               std::unique_ptr<framework::PerceptionStep> perception = nullptr);
  ~RobotProgram();  // joins (call the body side's shutdown first)
  RobotProgram(const RobotProgram&) = delete;
  RobotProgram& operator=(const RobotProgram&) = delete;

  // Replace the Motion step by a generator (before start()).
  void setMotion(std::unique_ptr<framework::MotionGenerator> motion);
  // Checks and orders the modules, announces the program to the body side,
  // then starts the threads (Named) or waits for the simulator's calls
  // (Inline). Throws ModuleError (nothing announced or started) if a module
  // reads a section nobody provides.
  void start(Threading threading = Threading::Named);
  // Waits for the threads to end (they end on shutdown).
  void join();

  // Inline only: one Motion step for the tick the body side has just
  // posted, one Perception step for the frame it has just posted. False if
  // nothing was posted, the run is over or the step threw (error() says
  // what); the step's answer is then missing, as a dead thread's would be.
  bool stepMotion();
  bool stepPerception();
  Threading threading() const { return threading_; }

  // Shares `io` with the Motion step (a generator holding the same
  // pointer); set it before the first Motion step. Null: none (STIFFEN never sent).
  void setLibagentIO(std::shared_ptr<LibagentIO> io) { io_ = std::move(io); }

  // Optional hook run by Motion after each command is sent (e.g. printing).
  void setAfterTick(std::function<void(const common::libagent::SensorValues&, int64_t)> f) {
    after_tick_ = std::move(f);
  }

  const std::string& tag() const { return tag_; }
  int64_t motionTicks() const { return motion_ticks_.load(); }
  int64_t perceptionFrames() const { return perception_frames_.load(); }
  // The camera images the Perception thread reads (null: no rendering).
  const common::libagent::CameraImages* images() const { return conn_->camera().images(); }
  // The behaviour module's configuration (agent/behaviour's), its camera
  // field of view the body's lens after start(); null without one.
  const behaviour::BehaviourConfig* behaviourConfig() const {
    return cfg_.behaviour_config ? &cfg_.behaviour_config->behaviour : nullptr;
  }
  // Attached by name: the simulator process has gone (killed) without ending the run.
  bool simulatorGone() const { return !conn_->shutdown() && !conn_->simulatorAlive(); }
  // First exception a thread died of (empty if none).
  std::string error() const;

  // The program's Blackboard (read it between lock-step cycles, e.g. in tests).
  blackboard::Blackboard& board() { return board_; }
  const framework::ModuleSchedule& schedule() const { return schedule_; }

 private:
  void motionLoop();
  void perceptionLoop();
  // One step of each thread's loop, after its wake-up (both modes).
  void motionStep();
  void perceptionStep();
  void fail(const std::string& thread, const std::exception& e);

  std::unique_ptr<BodyConnection> conn_;
  std::string tag_;
  ProgramConfig cfg_;
  blackboard::Blackboard board_;
  framework::ModuleSchedule schedule_;
  // The team transport over the extension object's team link (null: none).
  std::unique_ptr<comms::TeamTransport> team_link_;
  common::libagent::JointValues pending_{};  // the effector's command, sent after the Motion modules
  std::shared_ptr<LibagentIO> io_;           // libagent's extras for the Motion step (null: none)
  std::function<void(const common::libagent::SensorValues&, int64_t)> after_tick_;
  Threading threading_ = Threading::Named;
  bool with_perception_ = false;
  bool failed_ = false;          // inline: a step threw; no more steps
  double last_frame_time_ = -1;  // s, Perception's previous frame (-1: none yet)
  std::thread motion_thread_, perception_thread_;
  std::atomic<int64_t> motion_ticks_{0}, perception_frames_{0};
  mutable std::mutex error_mutex_;
  std::string error_;
};

}  // namespace agent::program
