// The sensor packet LoLA sends each 12 ms cycle: a plain struct with units,
// and its encoding, a msgpack map byte for byte as LoLA's (896 bytes).
//
// The encoding's layout is identical for every packet whatever the values:
// every number is a float32 (0xca + 4 bytes big-endian), the 25-element
// arrays have array16 headers, Status values are positive fixints (clamped
// to 0..3), RobotConfig strings are padded or cut to LoLA's lengths. B-Human's
// client parses the first packet only and reads every later one through the
// byte offsets it cached (docs/lola.md).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/lola/Float32.hpp"
#include "sim/lola/Protocol.hpp"

namespace simswift::lola {

using JointArray = std::array<float, kNumJoints>;  // LoLA joint order (Protocol.hpp)
using PacketBytes = std::array<std::uint8_t, kSensorPacketBytes>;

struct SensorPacket {
  JointArray position{};     // rad, measured joint angles
  JointArray stiffness{};    // 0..1, as commanded
  JointArray temperature{};  // deg C, motor temperature
  JointArray current{};      // A, motor current
  std::array<std::uint8_t, kNumJoints> status{};  // 0 normal, 1 hot, 2 very hot (stiffness reduced), 3 critical (stiffness 0)
  std::array<float, kNumBattery> battery{};       // see Protocol.hpp Battery: charge 0..1, status bits, A, deg C
  // m/s², torso frame with LoLA's sign: the public clients negate all three
  // components, so an upright robot reports about (0, 0, -9.81).
  std::array<float, 3> accelerometer{};
  std::array<float, 3> gyroscope{};  // rad/s, right-handed (counter-clockwise positive; the V5 is the opposite)
  std::array<float, 2> angles{};     // rad: AngleX (torso roll), AngleY (torso pitch)
  std::array<float, 2> sonar{};      // m: left, right
  std::array<float, kNumFsrs> fsr{};    // kg per sensor, order Fsr (Protocol.hpp)
  std::array<float, kNumTouch> touch{}; // 0 or 1, order Touch (Protocol.hpp)
  // Body id, body version, head id, head version (lengths kRobotConfigLengths).
  std::array<std::string, 4> robot_config{"SIMSWIFT000000BODY00", "6.0.0", "SIMSWIFT000000HEAD00", "6.0.0"};
};

// "" when every RobotConfig string has LoLA's length and is printable ASCII,
// otherwise a message naming the first that does not (for configuration
// checks: the encoder itself pads with '0' or cuts, so the packet stays 896 bytes).
std::string checkRobotConfig(const std::array<std::string, 4>& config);

// The packet as LoLA sends it: exactly kSensorPacketBytes bytes.
PacketBytes encodeSensorPacket(const SensorPacket& packet);

// writeFloat32: the one writer of LoLA's numbers (common/lola/Float32.hpp).

// Reads a sensor packet back (tests, tools). Strict: the 13 keys in
// kSensorKeys' order with their lengths, float32 numbers, Status as positive
// fixints, 4 strings. Returns std::nullopt and sets `error` otherwise.
std::optional<SensorPacket> decodeSensorPacket(const std::uint8_t* data, std::size_t size, std::string* error = nullptr);

}  // namespace simswift::lola
