// Where each element of LoLA's FSR, Touch, Battery and Sonar arrays lives in
// the V5's libagent sensor block: the one mapping both directions use (the
// simulator filling a V6 packet from its sensors, sim/lola/LolaBody.cpp;
// the robot program's client reading a packet into the V5's slots,
// common/lola/LolaConnection.cpp). The orders on LoLA's side are
// common/lola/Protocol.hpp's.
#pragma once

#include <array>

#include "common/lola/Protocol.hpp"

namespace common::lola {

// -1: LoLA has the value, the V5's block no slot for it (left 0 in a
// packet, dropped when read back).
constexpr int kNoSensorSlot = -1;

// libagent::Sensors index of each FSR (kg on both).
extern const std::array<int, kNumFsrs> kFsrSlots;
// libagent::Sensors index of each Touch value; the hands' touch sensors
// have none (not simulated: nothing touches them).
extern const std::array<int, kNumTouch> kTouchSlots;
// libagent::Sensors index of each Battery value: charge and current; the
// status bits and the temperature have none.
extern const std::array<int, kNumBattery> kBatterySlots;
// Index in libagent's sonar array of LoLA's two Sonar values (left, right):
// the first echo of each side, m.
extern const std::array<int, 2> kSonarEchoes;

}  // namespace common::lola
