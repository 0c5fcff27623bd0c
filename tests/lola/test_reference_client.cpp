// The robot program's LoLA client (common/lola/LolaConnection): what it
// writes is what real clients write (every number a float32), and what it
// reads back from simswift's packet is what the simulator put there (one
// slot mapping, common/lola/Slots.hpp, both directions).
#include <gtest/gtest.h>

#include <msgpack.hpp>

#include "common/lola/LolaConnection.hpp"
#include "common/lola/Slots.hpp"
#include "sim/lola/LolaBody.hpp"
#include "sim/lola/SensorPacket.hpp"

namespace al = common::libagent;
namespace S = al::Sensors;
namespace cl = common::lola;

// Issue 45: msgpack-c's pack_float wrote 0.0f and 1.0f as integers; real
// clients (B-Human, HULKs, rUNSWift, nao_lola) send float32 for every number.
TEST(ReferenceClient, WritesEveryNumberAsFloat32LikeRealClients) {
  al::JointValues j{};
  for (int i = 0; i < al::kNumJoints; ++i) {
    j.angles[i] = i % 3 == 0 ? 0.f : (i % 3 == 1 ? 1.f : -0.5f);  // whole numbers too
    j.stiffnesses[i] = i % 2 == 0 ? 1.f : 0.f;
  }
  const std::string map = cl::actuatorMap(j);
  const msgpack::object_handle h = msgpack::unpack(map.data(), map.size());
  const msgpack::object& m = h.get();
  ASSERT_EQ(m.type, msgpack::type::MAP);
  ASSERT_EQ(m.via.map.size, 2u);
  for (std::uint32_t k = 0; k < 2; ++k) {
    const msgpack::object& a = m.via.map.ptr[k].val;
    ASSERT_EQ(a.type, msgpack::type::ARRAY);
    ASSERT_EQ(a.via.array.size, 25u);
    for (std::uint32_t i = 0; i < 25; ++i)
      EXPECT_EQ(a.via.array.ptr[i].type, msgpack::type::FLOAT32) << m.via.map.ptr[k].key.as<std::string>() << "[" << i << "]";
  }
  // 2 keys: fixmap, 2 fixstr keys (9 + 10 bytes), 2 array16 headers, 50 float32s.
  EXPECT_EQ(map.size(), 1u + 9 + 10 + 2 * 3 + 50 * 5);
}

// The FSRs, Touch, Battery and Sonar the simulator puts in a V6 packet come
// back in the same V5 slots through the program's client.
TEST(ReferenceClient, ReadsBackTheSlotsTheSimulatorFilled) {
  al::SensorValues v{};
  for (int i = 0; i < cl::kNumFsrs; ++i) v.sensors[cl::kFsrSlots[i]] = 0.1f * (i + 1);
  for (int i = 0; i < cl::kNumTouch; ++i)
    if (cl::kTouchSlots[i] != cl::kNoSensorSlot) v.sensors[cl::kTouchSlots[i]] = (i % 2) ? 1.f : 0.f;
  v.sensors[S::Battery_Charge] = 0.75f;
  v.sensors[S::Battery_Current] = -1.25f;
  for (int i = 0; i < al::kNumSonars; ++i) v.sonar[i] = 0.3f + 0.01f * i;
  const simswift::lola::PacketBytes b = simswift::lola::encodeSensorPacket(simswift::lola::toLolaPacket(v, {}));
  const al::SensorValues back = cl::sensorValuesFromPacket(b.data(), b.size());
  for (int i = 0; i < cl::kNumFsrs; ++i) EXPECT_EQ(back.sensors[cl::kFsrSlots[i]], v.sensors[cl::kFsrSlots[i]]) << i;
  for (int i = 0; i < cl::kNumTouch; ++i)
    if (cl::kTouchSlots[i] != cl::kNoSensorSlot)
      EXPECT_EQ(back.sensors[cl::kTouchSlots[i]], v.sensors[cl::kTouchSlots[i]]) << i;
  EXPECT_EQ(back.sensors[S::Battery_Charge], 0.75f);
  EXPECT_EQ(back.sensors[S::Battery_Current], -1.25f);
  EXPECT_EQ(back.sonar[0], v.sonar[0]);
  EXPECT_EQ(back.sonar[al::kNumSonars / 2], v.sonar[al::kNumSonars / 2]);
}
