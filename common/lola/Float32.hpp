// The one writer of LoLA's numbers, both directions: the simulator's sensor
// packet (sim/lola/SensorPacket.cpp), its test encoder of actuator maps
// (sim/lola/ActuatorDecoder.cpp) and the robot program's client
// (common/lola/LolaConnection.cpp). Always msgpack float32, as LoLA and the
// real clients send every number: not msgpack::packer::pack_float, which in
// msgpack-c 4 writes a float with an integral value (0, 1, -3) as an
// integer (msgpack/v1/pack.hpp pack_float).
#pragma once

#include <cstddef>

namespace common::lola {

constexpr std::size_t kFloat32Bytes = 5;  // 0xca, then the IEEE 754 bits big-endian

// Writes `value` as a msgpack float32 at `out` (kFloat32Bytes bytes).
void writeFloat32(char* out, float value);

}  // namespace common::lola
