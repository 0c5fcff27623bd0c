// The body's end of libagent: the simulator plays the NAO's DCM side for one
// robot. It owns the robot's AgentBlock (+ CameraBlock) and tick semaphore,
// either in this process's memory (builtin robot programs) or as named POSIX
// objects another process attaches to (external robot programs).
//
// Per 10 ms cycle: publishSensors() fills a triple-buffer slot and posts the
// tick semaphore -- only if its value is <= 0, otherwise the robot program
// did not consume the last tick and the cycle counts as skipped. After
// kContactLostCycles consecutive skipped cycles contact is lost:
// readActuators() then returns the safe sit (crouch posture, stiffness
// agent::program::kSafeSitStiffness) instead of the stale command, until the
// program consumes a tick again.
#pragma once

#include <semaphore.h>

#include <cstdint>
#include <memory>
#include <string>

#include "agent/libagent/AgentConnection.hpp"
#include "agent/libagent/AgentShared.hpp"
#include "agent/libagent/SharedNames.hpp"
#include "agent/program/Postures.hpp"

namespace simswift::bridge {

using agent::libagent::ActuatorCommand;
using agent::libagent::AgentBlock;
using agent::libagent::CameraBlock;
using agent::libagent::SensorValues;

struct BridgeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

constexpr int kContactLostCycles = 50;

class BodyHost {
 public:
  enum class Mode { InProcess, Named };
  // Named mode creates /libagent-memory-<suffix> and /libagent-semaphore-<suffix>
  // with mode 0600 and O_EXCL (a leftover of a crashed run is an error naming
  // the object and how to remove it). `initial` is the command readActuators()
  // returns until the program writes one.
  BodyHost(int team, int player, Mode mode,
           const agent::libagent::JointValues& initial = agent::program::postureCommand(agent::program::Posture::Stand));
  ~BodyHost();  // unlinks the named objects
  BodyHost(const BodyHost&) = delete;
  BodyHost& operator=(const BodyHost&) = delete;

  int team() const { return team_; }
  int player() const { return player_; }
  const std::string& tag() const { return tag_; }  // "t1p2"
  Mode mode() const { return mode_; }
  const std::string& memoryName() const { return memory_name_; }
  const std::string& semaphoreName() const { return semaphore_name_; }

  AgentBlock* block() { return &shm_->agent; }
  CameraBlock* camera() { return &shm_->camera; }
  sem_t* tickSemaphore() { return tick_; }
  // An in-process connection for a builtin robot program.
  agent::libagent::AgentConnection connect();

  // Writes sensors (+ sim time, tick) as the latest slot, then posts the tick
  // semaphore or counts a skipped cycle. Returns true if it posted.
  bool publishSensors(const SensorValues& values, int64_t sim_time_us, int64_t tick);
  // The latest actuator command (or the safe sit if contact is lost).
  ActuatorCommand readActuators();

  // Lock-step: waits (wall clock, for the watchdog only) for motion_done.
  // False on timeout.
  bool waitMotionDone(double timeout_s);
  // 30 Hz camera handshake (only if the program has a Perception thread).
  bool hasPerception() const { return shm_->camera.consumer.load() != 0; }
  void publishFrame(const agent::libagent::CameraFrame& frame);
  bool waitPerceptionDone(double timeout_s);

  // Set by the program when it is ready (see AgentConnection::announce).
  bool attached() const { return shm_->agent.lockstep.attached.load() != 0; }
  // Sets shutdown and wakes the program's threads.
  void shutdown();

  bool contactLost() const { return contact_lost_; }
  int64_t skippedCycles() const { return skipped_total_; }
  int consecutiveSkipped() const { return skipped_run_; }
  int64_t contactLostEvents() const { return contact_lost_events_; }

 private:
  int team_, player_;
  std::string tag_;
  Mode mode_;
  std::string memory_name_, semaphore_name_;
  agent::libagent::SimRobotShm* shm_ = nullptr;
  std::unique_ptr<agent::libagent::SimRobotShm> owned_;  // in-process
  sem_t* tick_ = nullptr;
  sem_t tick_local_{};
  int skipped_run_ = 0;
  int64_t skipped_total_ = 0;
  int64_t contact_lost_events_ = 0;
  bool contact_lost_ = false;
};

// Unlinks every registered named object at exit and on SIGINT/SIGTERM (then
// re-raises the signal), so an interrupted run leaves nothing in /dev/shm.
namespace cleanup {
void registerShm(const std::string& name);
void registerSem(const std::string& name);
void unregister(const std::string& name);
// Unlinks everything registered by this process now (e.g. before _exit when
// a robot thread hangs and cannot be joined).
void removeAll();
}  // namespace cleanup

}  // namespace simswift::bridge
