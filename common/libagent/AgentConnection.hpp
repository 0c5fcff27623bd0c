// The robot code's end of libagent: what Motion and Perception use to talk to
// the body, whether the body is simswift in the same process, simswift in
// another process (named shared memory), or -- with the bare names -- a NAO.
//
// Per 10 ms cycle Motion does exactly what libagent's clients do: waitTick()
// (sem_wait on the tick semaphore), readSensors() (copy sensors_latest into
// sensors_read, read that slot), compute, writeActuators() (fill a slot that
// is neither latest nor being read, then set actuators_latest). With simswift
// it also uses the extension object (SimExtension.hpp): simulated time,
// announce(), the camera frame handshake, shutdown, and a wake-up post after
// each command. Attached by name it notices a simulator that died (its pid
// in the extension) within a second and ends instead of waiting forever.
//
// Every hand-over is ordered by an atomic, not by the semaphore alone: the
// sensor and actuator indices (loadIndex/storeIndex) for the tick, the
// camera's sequence numbers (CameraShared.hpp) for frames. Semaphores do
// order memory on a real machine, but ThreadSanitizer (GCC 12) has no
// sem_clockwait interceptor and would see no edge through the named waits.
#pragma once

#include <semaphore.h>

#include <cstdint>
#include <stdexcept>
#include <string>

#include "common/libagent/AgentShared.hpp"
#include "common/libagent/CameraImages.hpp"
#include "common/libagent/CameraShared.hpp"
#include "common/libagent/SharedNames.hpp"
#include "common/libagent/SimExtension.hpp"

namespace common::libagent {

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
  // In-process: the simulator owns `block`, `tick` and `ext`.
  AgentConnection(AgentData* block, sem_t* tick, SimExtension* ext);
  // In-process, the extension object alone: the camera frames, game state
  // and team link of a body whose ticks come another way (LoLA's socket,
  // common/lola). Only announce() and the Perception side may be used.
  static AgentConnection extensionOnly(SimExtension* ext);

  // By name (simulation rule: N = team * 11 + player). Throws AgentError
  // with a message saying what to check.
  static AgentConnection attachByName(int team, int player);
  // The same with explicit names (e.g. bareNames()).
  static AgentConnection attach(const RobotNames& names);

  AgentConnection(AgentConnection&& other) noexcept;
  AgentConnection& operator=(AgentConnection&&) = delete;
  AgentConnection(const AgentConnection&) = delete;
  ~AgentConnection();

  // Tells the simulator this is a simswift-aware program; call before the
  // threads answer their first tick. `perception` = a thread will wait on
  // camera frames.
  void announce(bool perception);

  // Blocks until the body posts the next tick. False when the run is over or
  // the simulator is gone (then a message on stderr says which).
  bool waitTick();
  // Inline (the simulator runs the program's steps on its own thread, one
  // after the other): takes the tick it has posted, without blocking. False
  // if none is posted or the run is over.
  bool takeTick();
  // Triple-buffer read of the latest sensors (copy).
  SensorValues readSensors();
  // The button presses of the slot last read.
  ButtonPresses buttons() const { return block_->buttons[last_slot_]; }
  // Triple-buffer write of a command, then the wake-up post.
  void writeActuators(const ActuatorCommand& cmd);
  void writeActuators(const JointValues& joints, const LedCommand* leds = nullptr,
                      SonarMode sonar = 0, bool stiffen = false, const std::string& say = {});

  // Perception side. waitFrame() returns false when the run is over;
  // perceptionDone() answers the frame it took (camera.frames_done).
  bool hasCamera() const { return ext_ != nullptr; }
  bool waitFrame();
  // Inline: takes a posted frame without blocking (see takeTick()).
  bool takeFrame();
  const CameraFrame& frame() const { return ext_->camera.frame; }
  void perceptionDone();
  // The rendered camera images, or null when the simulator does not render.
  // Valid for a frame when frame().images_valid is 1; read them between
  // waitFrame() and perceptionDone() (the simulator writes them before
  // posting frame_ready and not again until perception_done).
  const CameraImages* images() const { return images_; }
  // In-process: the simulator hands over its images block (before start).
  void setImages(const CameraImages* images) { images_ = images; }

  // Simulated time (us) and tick of the sensors last read.
  int64_t simTimeUs() const { return ext_->slot_time_us[last_slot_]; }
  int64_t tick() const { return ext_->slot_tick[last_slot_]; }
  bool shutdown() const { return ext_->shutdown.load() != 0; }
  // Attached by name: false once the simulator process has gone.
  bool simulatorAlive() const;

  AgentData* block() { return block_; }
  SimExtension* extension() { return ext_; }
  const std::string& name() const { return names_.memory; }

 private:
  AgentConnection() = default;
  void release();
  bool waitOn(sem_t* s, const char* what);

  AgentData* block_ = nullptr;
  sem_t* tick_ = nullptr;
  SimExtension* ext_ = nullptr;
  const CameraImages* images_ = nullptr;
  int last_slot_ = 0;
  // Named mode only:
  bool named_ = false;
  RobotNames names_{"<in-process>", "", "", ""};
  void* block_map_ = nullptr;
  void* ext_map_ = nullptr;
  void* images_map_ = nullptr;
  int sim_pid_ = 0;
  uint64_t sim_start_ = 0;
  int64_t frame_taken_ = 0;  // camera.frames_posted seen by the last waitFrame()
};

}  // namespace common::libagent
