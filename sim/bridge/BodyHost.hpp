// The body's end of libagent: the simulator plays the NAO's DCM side for one
// robot. It sets up all of the robot's shared objects in one place (the
// libagent block and semaphore, simswift's extension object and, when
// rendering, the camera images), either in this process's memory (builtin
// robot programs) or as named POSIX objects another process attaches to
// (external robot programs; names in common/libagent/SharedNames.hpp).
//
// Per 10 ms cycle: publishSensors() fills a sensor slot and posts the tick
// semaphore -- only if its value is <= 0, otherwise the program did not take
// the last tick and the cycle counts as skipped.
//
// Every hand-over is ordered by an atomic the other side loads after its
// wait (the sensor/actuator indices; the camera's frames_posted/frames_done):
// ThreadSanitizer then sees it (it has no sem_clockwait interceptor), and a
// stray semaphore post is never taken for an answer.
//
// Lock-step (default): after consuming a command readActuators() parks
// actuators_latest on kActuatorsParked; waitAnswer() returns once a valid
// index reappears, i.e. once the program's Motion wrote a slot and set
// actuators_latest exactly as libagent's clients do. Nothing else is asked
// of the program.
//
// Free-running (SyncMode::FreeRunning, --realtime): nothing waits;
// readActuators() returns the latest command. After more than
// kContactLostCycles consecutive skipped cycles contact is lost.
//
// What the body does with the commands is libagent's (LibagentBehaviour.hpp):
// start limp or stiff, `standing` and STIFFEN, counted chest clicks in
// ButtonPresses, the release's sit after a contact loss and limp until
// stiffened. The block is the one of the robot's rUNSWift release
// (Releases.hpp: 2016, 2017 or 2018); block() is the 2017 one's (null for
// the others).
//
// Named objects: opened with O_CREAT (a program that started first and
// created empty ones is adopted: the block is sized and initialised), mode
// 0600. The extension records this simulator's pid; objects left by a killed
// run (owner pid gone) are taken over, a robot owned by a live simulator is
// refused with an error naming its pid. All are unlinked on destruction, at
// exit and on SIGINT/SIGTERM.
#pragma once

#include <semaphore.h>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "common/libagent/AgentConnection.hpp"
#include "common/libagent/AgentShared.hpp"
#include "common/libagent/CameraImages.hpp"
#include "common/libagent/SharedNames.hpp"
#include "common/libagent/SimExtension.hpp"
#include "common/nao/Postures.hpp"
#include "sim/bridge/BodySide.hpp"
#include "sim/bridge/Cleanup.hpp"
#include "sim/bridge/ExtensionObject.hpp"
#include "sim/bridge/LibagentBehaviour.hpp"
#include "sim/bridge/Releases.hpp"
#include "sim/bridge/StaleObjects.hpp"

namespace simswift::bridge {

using common::libagent::ActuatorCommand;
using common::libagent::AgentData;
using common::libagent::CameraBlock;
using common::libagent::SensorValues;
using common::libagent::SimExtension;
using common::libagent::SyncMode;

struct BridgeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

constexpr int kContactLostCycles = LibagentBehaviour::kMaxSkips;  // lost after more skipped cycles than this

struct BodyHostOptions {
  bool bare_names = false;  // /libagent-memory etc. without the team/player suffix
  bool images = false;      // set up the camera images block too
  Release release = Release::R2017;      // the program's block layout and names
  StartMode start = StartMode::Stiff;    // libagent: start stiff (standing set) or limp
};

class BodyHost final : public BodySide {
 public:
  enum class Mode { InProcess, Named };
  // `initial` is the command readActuators() returns until the program
  // writes one. Throws BridgeError (bad team/player, objects owned by a
  // live simulator, system errors).
  BodyHost(int team, int player, Mode mode,
           const common::libagent::JointValues& initial = common::nao::postureCommand(common::nao::Posture::Stand),
           const BodyHostOptions& options = {});
  ~BodyHost();  // unlinks the named objects
  BodyHost(const BodyHost&) = delete;
  BodyHost& operator=(const BodyHost&) = delete;

  int team() const { return team_; }
  int player() const { return player_; }
  Mode mode() const { return mode_; }
  // BodySide: libagent, the NAO V5.
  BodyInterface interface() const override { return BodyInterface::Libagent; }
  const std::string& endpoint() const override { return names_.memory; }
  std::string attachHint() const override;
  std::map<std::string, std::string> placeholders() const override;
  const common::libagent::RobotNames& names() const { return names_; }
  const std::string& memoryName() const { return names_.memory; }

  AgentData* block() { return block_; }  // the 2017 block; null for other releases
  Release release() const { return options_.release; }
  const LibagentBehaviour& libagent() const { return libagent_; }
  bool standing() const;  // the block's `standing` flag
  SimExtension* extension() override { return ext_; }
  CameraBlock* camera() { return &ext_->camera; }
  sem_t* tickSemaphore() { return tick_; }
  // The camera images (null unless options.images).
  common::libagent::CameraImages* images() override { return images_; }
  // An in-process connection for a builtin robot program (2017 block only).
  common::libagent::AgentConnection connect();

  void setSync(SyncMode mode) override;
  SyncMode sync() const override { return sync_; }

  // Writes sensors (+ sim time, tick, button presses) as the latest slot,
  // then posts the tick semaphore or counts a skipped cycle. Returns true if
  // it posted.
  bool publishSensors(const SensorValues& values, int64_t sim_time_us, int64_t tick) override;
  // True once the program has published a command not yet consumed.
  bool answered() const override;
  // Lock-step: waits (wall clock, for the watchdog only) until answered().
  // False on timeout.
  bool waitAnswer(double timeout_s) override;
  // The latest command (consumed: lock-step parks actuators_latest), the
  // previous one if none is new, or the safe sit if contact is lost.
  ActuatorCommand readActuators() override;

  // A simswift-aware program has announced itself (AgentConnection::announce).
  bool clientAnnounced() const { return ext_->client_pid.load() != 0; }
  // 30 Hz camera handshake (only if the program has a Perception thread).
  bool hasPerception() const override { return camera_.consumer(); }
  void publishFrame(const common::libagent::CameraFrame& frame) override;
  bool waitPerceptionDone(double timeout_s) override;

  // Sets shutdown and wakes the program's threads.
  void shutdown() override;

  bool contactLost() const { return contact_lost_; }
  int64_t skippedCycles() const override { return skipped_total_; }
  int consecutiveSkipped() const { return skipped_run_; }
  int64_t contactLostEvents() const { return contact_lost_events_; }
  int64_t commandsRead() const { return commands_read_; }

 private:
  void setUpNamed();
  void takeOwnership(int fd);
  void initialise(const common::libagent::JointValues& initial);
  void releaseNamed();

  int team_, player_;
  Mode mode_;
  BodyHostOptions options_;
  common::libagent::RobotNames names_;
  void* raw_ = nullptr;                 // the release's block
  AgentData* block_ = nullptr;          // raw_ as the 2017 block (null otherwise)
  SimExtension* ext_ = nullptr;
  common::libagent::CameraImages* images_ = nullptr;
  // In-process storage.
  std::unique_ptr<unsigned char[]> own_block_;
  std::unique_ptr<SimExtension> own_ext_;
  std::unique_ptr<common::libagent::CameraImages> own_images_;
  sem_t tick_local_{};
  sem_t* tick_ = nullptr;
  bool named_set_up_ = false;

  SyncMode sync_ = SyncMode::LockStep;
  template <class F>
  decltype(auto) withBlock(F&& f);  // f(the release's block struct&)
  template <class F>
  decltype(auto) withBlock(F&& f) const;

  ActuatorCommand last_;                 // the program's latest command
  bool commanded_ = false;               // it has sent one
  LibagentBehaviour libagent_;
  std::array<float, common::libagent::kNumJoints> measured_{};  // angles of the last sensor slot (rad)
  int skipped_run_ = 0;
  int64_t skipped_total_ = 0;
  int64_t contact_lost_events_ = 0;
  int64_t commands_read_ = 0;
  CameraHandover camera_;      // the 30 Hz frames over ext_
  bool contact_lost_ = false;
};

}  // namespace simswift::bridge
