// The robot code's end of libagent: what Motion and Perception use to talk to
// the body, whether the body is simswift in the same process, simswift in
// another process (named shared memory), or -- with the bare names -- a NAO.
//
// Lock-step protocol (simswift): the body publishes sensors and posts the
// tick semaphore; Motion's waitTick() returns, it reads sensors, computes, and
// writeActuators() publishes the command and posts lockstep.motion_done, which
// the simulator waits for before the next physics tick. Perception likewise
// waits on camera.frame_ready and posts camera.perception_done.
#pragma once

#include <semaphore.h>

#include <cstdint>
#include <stdexcept>
#include <string>

#include "agent/libagent/AgentShared.hpp"
#include "agent/libagent/CameraImages.hpp"
#include "agent/libagent/CameraShared.hpp"

namespace agent::libagent {

struct AgentError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Everything Motion writes in one cycle (one triple-buffer slot).
struct ActuatorCommand {
  JointValues joints{};    // angles (rad) and stiffnesses (0..1, -1 limp) are used
  LedCommand leds{};
  SonarMode sonar = 0;
  bool stiffen = false;
  std::string say;         // truncated to kSayTextLength - 1 characters
};

class AgentConnection {
 public:
  // In-process: the simulator owns `block`, `tick` and `camera` (camera may
  // be null: no Perception handshake).
  AgentConnection(AgentBlock* block, sem_t* tick, CameraBlock* camera = nullptr);

  // By name: maps /libagent-memory-<suffix> and opens /libagent-semaphore-<suffix>
  // (suffix = team * kMaxPlayers + player). Checks magic and version.
  // Throws AgentError with a message saying what to check.
  static AgentConnection attachByName(int team, int player);
  // The same with explicit names (e.g. the bare robot names).
  static AgentConnection attachNamed(const std::string& memory, const std::string& semaphore);

  AgentConnection(AgentConnection&& other) noexcept;
  AgentConnection& operator=(AgentConnection&&) = delete;
  AgentConnection(const AgentConnection&) = delete;
  ~AgentConnection();

  // Tells the simulator this robot program is ready (threads about to wait).
  // `perception` = a thread will wait on camera frames.
  void announce(bool perception);

  // Blocks until the body posts the next tick. False when the run is over.
  bool waitTick();
  // Triple-buffer read of the latest sensors (copy).
  SensorValues readSensors();
  // Triple-buffer write of a command, then posts lockstep.motion_done.
  void writeActuators(const ActuatorCommand& cmd);
  void writeActuators(const JointValues& joints, const LedCommand* leds = nullptr,
                      SonarMode sonar = 0, bool stiffen = false, const std::string& say = {});
  void setStanding(bool standing) { block_->standing = standing; }

  // Perception side. waitFrame() returns false when the run is over.
  bool hasCamera() const { return camera_ != nullptr; }
  bool waitFrame();
  const CameraFrame& frame() const { return camera_->frame; }
  void perceptionDone();
  // The rendered camera images, or null when the simulator does not render.
  // Valid for a frame when frame().images_valid is 1; read them between
  // waitFrame() and perceptionDone() (the simulator writes them before
  // posting frame_ready and not again until perception_done).
  const CameraImages* images() const { return images_; }
  // In-process: the simulator hands over its images block (before start).
  void setImages(const CameraImages* images) { images_ = images; }

  // Simulated time (us) and tick of the sensors in the latest slot.
  int64_t simTimeUs() const { return block_->lockstep.sim_time_us; }
  int64_t tick() const { return block_->lockstep.tick; }
  bool shutdown() const { return block_->lockstep.shutdown.load() != 0; }

  AgentBlock* block() { return block_; }
  const std::string& name() const { return memory_name_; }

 private:
  AgentConnection() = default;
  void release();

  AgentBlock* block_ = nullptr;
  sem_t* tick_ = nullptr;
  CameraBlock* camera_ = nullptr;
  const CameraImages* images_ = nullptr;
  // Named mode only:
  void* images_mapping_ = nullptr;  // read-only map of the images block
  void* mapping_ = nullptr;
  size_t mapping_size_ = 0;
  bool named_sem_ = false;
  std::string memory_name_ = "<in-process>";
};

}  // namespace agent::libagent
