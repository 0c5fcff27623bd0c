// The robot program's end of LoLA, the NAO V6's robot interface (2019
// onwards): what a V6 team's program does, from the public facts
// (docs/lola.md): connect to the socket (/tmp/robocup on a robot), read one
// 896-byte sensor packet per 12 ms cycle, answer it with an actuator map
// (Position and Stiffness). The sensors are handed up in the V5's slot
// layout, units and signs (common/libagent/AgentShared.hpp, Inertial.hpp), so
// the robot code above reads one representation whatever the body: nothing
// in Motion changes between a V5 and a V6 (it takes its tick, 12 ms here,
// from the clock).
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "common/libagent/AgentShared.hpp"
#include "common/lola/Protocol.hpp"

namespace common::lola {

struct LolaError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A sensor packet (msgpack, read by key as HULKs' and rUNSWift's clients
// do) in the V5's slot layout: joints by name, the FSRs in kg, Touch to the
// button and bumper slots, the inertial values with the V5's signs (the
// legacy raw GyrX/GyrY/AccX/Y/Z slots, which the robot code does not read,
// stay 0), the two sonar echoes as the first of each side (the rest: no
// echo). Throws LolaError naming what is wrong.
libagent::SensorValues sensorValuesFromPacket(const std::uint8_t* data, std::size_t size);
// The answer to one packet: one map with Position and Stiffness (LoLA joint
// order; libagent's -1 "off" is LoLA's 0), float32 values.
std::string actuatorMap(const libagent::JointValues& joints);

class LolaConnection {
 public:
  // Connects to `path`, retrying every 10 ms for up to timeout_s of wall
  // clock (B-Human retries 10 x 10 ms, HULKs 60 x 1 s). Throws LolaError.
  static LolaConnection connect(const std::string& path, double timeout_s);
  LolaConnection(LolaConnection&& other) noexcept;
  LolaConnection& operator=(LolaConnection&&) = delete;
  LolaConnection(const LolaConnection&) = delete;
  ~LolaConnection();

  // Blocks until the next packet has arrived whole. False once the other
  // end has closed the socket (the run is over, or the robot has gone).
  bool waitTick();
  // Takes a packet that has arrived, without blocking when none has (a
  // program whose steps run on the simulator's thread). False if none.
  bool takeTick();
  // The last packet's sensors (sensorValuesFromPacket).
  libagent::SensorValues readSensors() const;
  // The program's own clock: packets read x LoLA's 12 ms cycle, us (LoLA
  // sends no time; a V6 program counts cycles or reads its clock).
  int64_t timeUs() const { return packets_ * kCycleUs; }
  int64_t packets() const { return packets_; }
  // Sends the answer (actuatorMap). False if the other end has gone.
  bool writeActuators(const libagent::JointValues& joints);
  bool closed() const { return fd_ < 0; }
  const std::string& path() const { return path_; }

 private:
  LolaConnection(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
  bool readRest(std::size_t have);  // completes packet_ after `have` bytes
  void close();
  int fd_ = -1;
  std::string path_;
  std::array<std::uint8_t, kSensorPacketBytes> packet_{};
  int64_t packets_ = 0;
};

}  // namespace common::lola
