// The body side of the seam: what a robot's body offers whatever drives it.
// One interface, one implementation per robot interface:
//   BodyHost   libagent, the NAO V5 (rUNSWift 2016/2017/2018 blocks in shared
//              memory, 10 ms): sim/bridge/BodyHost.hpp
//   LolaBody   LoLA, the NAO V6 (msgpack over a Unix socket, 12 ms):
//              sim/lola/LolaBody.hpp
// The Runner posts each robot's sensors here every tick and latches the
// answer from here; the program drivers (sim/programs/ProgramDriver.hpp) only
// wait for it. Which interface a robot has is the scenario's `libagent:` or
// `lola:` key (BodyInterface); its cycle is the robot's tick
// (sim/runner/Bodies.hpp, bodyCycleUs).
//
// The currency across it is the simulator's own sensor slot and command
// (common/libagent's SensorValues and ActuatorCommand: the V5 layout and units,
// sim/sensors fills them); an implementation translates them into its
// robot's protocol.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "common/libagent/AgentConnection.hpp"
#include "common/libagent/CameraImages.hpp"
#include "common/libagent/SimExtension.hpp"

namespace simswift::bridge {

// The robot interfaces simswift serves (their cycles and the factory:
// sim/runner/Bodies.hpp).
enum class BodyInterface : int { Libagent, Lola };

class BodySide {
 public:
  virtual ~BodySide() = default;
  BodySide(const BodySide&) = delete;
  BodySide& operator=(const BodySide&) = delete;

  virtual BodyInterface interface() const = 0;
  const std::string& tag() const { return tag_; }  // "t19p2"
  // What a program opens to reach this body (a shared-memory name, a socket
  // path), for messages.
  virtual const std::string& endpoint() const = 0;
  // What to start for this robot, said while its first answer is awaited.
  virtual std::string attachHint() const = 0;
  // A launched program's command placeholders this body adds to {team},
  // {player}, {seed} and {config} (libagent: {memory}, {number}, ...; LoLA:
  // {socket}, as the launched program sees it).
  virtual std::map<std::string, std::string> placeholders() const = 0;

  // Lock-step (default) or free-running (--realtime: the program is never
  // waited for after it attached; a missed cycle keeps the last command).
  virtual void setSync(common::libagent::SyncMode mode) = 0;
  virtual common::libagent::SyncMode sync() const = 0;

  // One tick: the robot's sensors as measured after this tick's physics, at
  // sim time t_us. True if the program was given the tick (false: it had
  // not taken the last one, or no program is connected yet).
  virtual bool publishSensors(const common::libagent::SensorValues& values, int64_t sim_time_us, int64_t tick) = 0;
  // The program has answered the last tick.
  virtual bool answered() const = 0;
  // Lock-step: waits up to timeout_s (wall clock; for the watchdog only,
  // never deciding what the answer is) for the answer. False on timeout.
  virtual bool waitAnswer(double timeout_s) = 0;
  // The program that was connected has gone (LoLA: its connection closed)
  // and none has connected since: a hand-started program is waited for as
  // at its first attach. libagent's block has no connection to lose.
  virtual bool programGone() const { return false; }
  // The command the body gets: the program's answer (consumed), or the last
  // one, or what the interface does on its own (libagent's limp start and sit).
  virtual common::libagent::ActuatorCommand readActuators() = 0;

  // The simulator's extension object beside the body (game state, team
  // link, camera frames); every body has one, a program may not read it.
  virtual common::libagent::SimExtension* extension() = 0;
  // The camera images block (null unless rendered for this robot's program).
  virtual common::libagent::CameraImages* images() = 0;
  // 30 Hz camera hand-over: the program has a Perception thread.
  virtual bool hasPerception() const = 0;
  virtual void publishFrame(const common::libagent::CameraFrame& frame) = 0;
  virtual bool waitPerceptionDone(double timeout_s) = 0;

  // The run ends: the program is told (where the interface can tell it).
  virtual void shutdown() = 0;
  virtual int64_t skippedCycles() const = 0;

 protected:
  explicit BodySide(std::string tag) : tag_(std::move(tag)) {}
  std::string tag_;
};

}  // namespace simswift::bridge
