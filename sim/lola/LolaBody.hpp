// The body side of a NAO V6: simswift is the robot's LoLA (docs/lola.md).
// Per robot one LolaServer on its own socket; each 12 ms tick one 896-byte
// sensor packet goes out and the program's actuator maps come back.
//
// What the body does beyond the bytes (docs/lola.md, "The body"):
// - Stiffness 0 at start: every joint limp until the program sends
//   Stiffness (as a V6 after LoLA starts; the public clients all send it
//   every cycle). A joint holds a Position only with stiffness.
// - Keys are remembered: a map without Position keeps the last positions,
//   one without Stiffness the last stiffnesses (LoLA's actuators hold
//   their value; the Webots controllers do the same).
// - Lock-step (default): the tick waits for the cycle's answer (the decoder
//   says which maps make one: ActuatorDecoder.hpp); a program that is slow
//   or stopped under gdb keeps the run waiting, up to the watchdog.
//   Free-running (--realtime): nothing waits; each cycle takes an answer
//   if one has arrived and otherwise keeps the last command (what the
//   Webots controllers do; real LoLA's behaviour is not public).
// - A client that disconnects, sends bytes that are not LoLA's or stops
//   reading is dropped (said once on stderr); the body keeps its last
//   command and the tick waits for a client to connect again.
// - Status: from the motor temperature model's temperatures, 0 below
//   status_hot (60 deg C), 1, then 2 from status_very_hot (70: where the
//   servo model's current limit starts to fall, ServoParams::hot_start), 3
//   from status_critical (90: hot_end). An assumption: LoLA's thresholds
//   are not public (LolaBodyOptions).
#pragma once

#include <array>
#include <memory>
#include <string>

#include "sim/bridge/BodySide.hpp"
#include "sim/bridge/BodyHost.hpp"
#include "sim/lola/LolaServer.hpp"

namespace simswift::lola {

struct LolaBodyOptions {
  std::string socket_path;  // where the program connects (LoLA's own: /tmp/robocup)
  // Body id, body version, head id, head version (checkRobotConfig).
  std::array<std::string, 4> robot_config = SensorPacket{}.robot_config;
  DecoderOptions decoder;
  bool named = false;   // the program is in another process: simswift's objects by name
  bool images = false;  // camera images for the program (simswift's images block)
  // Status thresholds, deg C (Status above).
  float status_hot = 60.f, status_very_hot = 70.f, status_critical = 90.f;
};

// The simulator's sensor slot (V5 layout and signs) as LoLA reports it.
// Pure: tests check each slot's translation.
SensorPacket toLolaPacket(const common::libagent::SensorValues& values, const LolaBodyOptions& options);

class LolaBody final : public bridge::BodySide {
 public:
  // Throws ServerError (socket path taken by a live server, too long, ...).
  LolaBody(int team, int player, const common::libagent::JointValues& initial, LolaBodyOptions options);
  ~LolaBody() override;

  bridge::BodyInterface interface() const override { return bridge::BodyInterface::Lola; }
  const std::string& endpoint() const override { return server_.path(); }
  std::string attachHint() const override;
  std::map<std::string, std::string> placeholders() const override;
  void setSync(common::libagent::SyncMode mode) override { sync_ = mode; }
  common::libagent::SyncMode sync() const override { return sync_; }

  bool publishSensors(const common::libagent::SensorValues& values, int64_t sim_time_us, int64_t tick) override;
  bool answered() const override { return answered_; }
  bool waitAnswer(double timeout_s) override;
  bool programGone() const override { return server_.clientsAccepted() > 0 && !server_.connected(); }
  common::libagent::ActuatorCommand readActuators() override;
  common::libagent::SimExtension* extension() override { return objects_->extension(); }
  common::libagent::CameraImages* images() override { return objects_->images(); }
  bool hasPerception() const override { return objects_->hasPerception(); }
  void publishFrame(const common::libagent::CameraFrame& frame) override { objects_->publishFrame(frame); }
  bool waitPerceptionDone(double timeout_s) override { return objects_->waitPerceptionDone(timeout_s); }
  void shutdown() override;
  int64_t skippedCycles() const override { return skipped_; }

  const LolaServer& server() const { return server_; }
  int64_t answers() const { return answers_; }

 private:
  void take(const Exchange& e);  // an exchange's outcome: the answer kept, a dropped client said
  LolaBodyOptions options_;
  LolaServer server_;
  // simswift's objects beside the body, as a V5 robot has them (BodyHost,
  // in this process or by libagent's names): the extension object (camera
  // frames, game state, team link) and the camera images, which the
  // reference program reads on a V6 as on a V5. Its libagent block is not
  // used (the joints go over the socket).
  std::unique_ptr<bridge::BodyHost> objects_;
  common::libagent::SyncMode sync_ = common::libagent::SyncMode::LockStep;
  PacketBytes packet_{};
  bool sent_ = false;      // this cycle's packet went out
  bool answered_ = false;  // and its answer is in `pending_`
  ActuatorCommand pending_;
  JointArray position_{};   // rad, LoLA order: what the joints are told to hold
  JointArray stiffness_{};  // 0..1: 0 at start
  int64_t skipped_ = 0;
  int64_t answers_ = 0;
  int64_t tick_ = 0;
};

}  // namespace simswift::lola
