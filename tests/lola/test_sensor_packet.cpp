// The sensor packet: LoLA's 896 bytes, keys in order, lengths, encodings,
// and a layout that does not change with the values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include <msgpack.hpp>

#include "sim/lola/SensorPacket.hpp"

using namespace simswift::lola;

namespace {

// A packet with every value different from the defaults (seeded).
SensorPacket randomPacket(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1000.f, 1000.f);
  SensorPacket p;
  for (auto* a : {&p.position, &p.stiffness, &p.temperature, &p.current})
    for (float& v : *a) v = u(rng);
  for (auto& s : p.status) s = static_cast<std::uint8_t>(rng() % 4);
  for (float& v : p.battery) v = u(rng);
  for (float& v : p.accelerometer) v = u(rng);
  for (float& v : p.gyroscope) v = u(rng);
  for (float& v : p.angles) v = u(rng);
  for (float& v : p.sonar) v = u(rng);
  for (float& v : p.fsr) v = u(rng);
  for (float& v : p.touch) v = static_cast<float>(rng() % 2);
  // Integral values too (msgpack-c would pack those as integers), and the
  // Touch values are 0 or 1.
  p.position[3] = 1.f;
  p.current[0] = -3.f;
  p.battery[BatteryStatus] = 128.f;
  p.robot_config = {"ABCDEFGHIJKLMNOPQRST", "6.0.4", "01234567890123456789", "6.1.0"};
  return p;
}

// Offsets (packet bytes) of every value payload, from the encoding rules:
// a 1-byte fixmap, per key a fixstr, an array header (3 bytes for 25
// elements, else 1), float32 (marker + 4 bytes) or fixint (1 byte) values.
struct Layout {
  std::vector<std::size_t> floats;  // offset of each float32 marker 0xca
  std::vector<std::size_t> status;  // offset of each Status fixint
};
Layout expectedLayout() {
  Layout l;
  std::size_t at = 1;
  for (const KeySpec& k : kSensorKeys) {
    at += 1 + k.name.size();
    at += k.length > 15 ? 3 : 1;
    if (k.name == "RobotConfig") {
      for (std::size_t n : kRobotConfigLengths) at += 1 + n;
    } else if (k.name == "Status") {
      for (int i = 0; i < k.length; ++i) l.status.push_back(at++);
    } else {
      for (int i = 0; i < k.length; ++i) {
        l.floats.push_back(at);
        at += 5;
      }
    }
  }
  EXPECT_EQ(at, kSensorPacketBytes);
  return l;
}

}  // namespace

TEST(SensorPacket, Is896BytesWhateverTheValues) {
  EXPECT_EQ(encodeSensorPacket(SensorPacket{}).size(), 896u);
  SensorPacket extreme = randomPacket(1);
  extreme.position[0] = std::numeric_limits<float>::quiet_NaN();
  extreme.position[1] = std::numeric_limits<float>::infinity();
  extreme.fsr[0] = 1e38f;
  extreme.status[0] = 200;                                     // clamped to 3
  extreme.robot_config = {"short", "6", std::string(40, 'X'), "6.0.0.1"};  // fitted to 20/5/20/5
  const PacketBytes b = encodeSensorPacket(extreme);
  std::string error;
  const auto back = decodeSensorPacket(b.data(), b.size(), &error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(back->status[0], 3);
  EXPECT_EQ(back->robot_config[0], "short000000000000000");
  EXPECT_EQ(back->robot_config[1], "60000");
  EXPECT_EQ(back->robot_config[2], std::string(20, 'X'));
  EXPECT_EQ(back->robot_config[3], "6.0.0");
  EXPECT_TRUE(std::isnan(back->position[0]));
  EXPECT_TRUE(std::isinf(back->position[1]));
}

TEST(SensorPacket, KeysInOrderWithLoLAsLengthsAndEncodings) {
  const PacketBytes b = encodeSensorPacket(randomPacket(2));
  // Read with msgpack-c (not our decoder): one map, nothing left over.
  std::size_t off = 0;
  msgpack::object_handle h = msgpack::unpack(reinterpret_cast<const char*>(b.data()), b.size(), off);
  EXPECT_EQ(off, 896u);
  const msgpack::object& m = h.get();
  ASSERT_EQ(m.type, msgpack::type::MAP);
  ASSERT_EQ(m.via.map.size, 13u);
  EXPECT_EQ(b[0], 0x8d);  // fixmap of 13
  // Real LoLA's order: a real V6's packet quoted in NaoTH's Tools/LolaData.h.
  const char* const order[13] = {"RobotConfig", "Accelerometer", "Angles",    "Battery",     "Current",
                                 "FSR",         "Gyroscope",     "Position",  "Sonar",       "Stiffness",
                                 "Temperature", "Touch",         "Status"};
  const std::uint32_t lengths[13] = {4, 3, 2, 4, 25, 8, 3, 25, 2, 25, 25, 14, 25};
  for (int k = 0; k < 13; ++k) {
    const msgpack::object_kv& kv = m.via.map.ptr[k];
    EXPECT_EQ(kv.key.as<std::string>(), order[k]);
    ASSERT_EQ(kv.val.type, msgpack::type::ARRAY) << order[k];
    ASSERT_EQ(kv.val.via.array.size, lengths[k]) << order[k];
    for (std::uint32_t i = 0; i < lengths[k]; ++i) {
      const msgpack::object& v = kv.val.via.array.ptr[i];
      if (k == 12) {
        EXPECT_EQ(v.type, msgpack::type::POSITIVE_INTEGER);
        EXPECT_LE(v.via.u64, 3u);
      } else if (k == 0) {
        ASSERT_EQ(v.type, msgpack::type::STR);
        EXPECT_EQ(v.via.str.size, i % 2 == 0 ? 20u : 5u);
      } else {
        EXPECT_EQ(v.type, msgpack::type::FLOAT32) << order[k] << "[" << i << "]";
      }
    }
  }
  // The joint order's ends and the hip (index 7 drives both hips).
  EXPECT_EQ(kJointNames[0], "HeadYaw");
  EXPECT_EQ(kJointNames[7], "LHipYawPitch");
  EXPECT_EQ(kJointNames[13], "RHipRoll");
  EXPECT_EQ(kJointNames[24], "RHand");
  for (auto name : kJointNames) EXPECT_NE(name, "RHipYawPitch");
}

TEST(SensorPacket, ValuesSitAtTheSameBytesInEveryPacket) {
  const Layout layout = expectedLayout();
  ASSERT_EQ(layout.floats.size(), 4u * 25 + 4 + 3 + 3 + 2 + 2 + 8 + 14);
  EXPECT_EQ(layout.status.back(), 895u);  // Status ends the packet
  const PacketBytes zero = encodeSensorPacket(SensorPacket{});
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const PacketBytes other = encodeSensorPacket(randomPacket(seed));
    std::vector<bool> value_byte(896, false);
    for (std::size_t at : layout.floats) {
      ASSERT_EQ(zero[at], 0xca) << "float marker at " << at;
      ASSERT_EQ(other[at], 0xca) << "float marker at " << at << ", seed " << seed;
      for (int i = 1; i <= 4; ++i) value_byte[at + i] = true;
    }
    for (std::size_t at : layout.status) {
      ASSERT_LT(other[at], 0x80) << "Status fixint at " << at;
      value_byte[at] = true;
    }
    // RobotConfig strings (the first key: after the map byte, its 12-byte
    // key and the fixarray byte) belong to the layout here: same lengths,
    // other text.
    const std::size_t config_text = 1 + 12 + 1;
    for (std::size_t i = config_text; i < config_text + (1 + 20 + 1 + 5 + 1 + 20 + 1 + 5); ++i) value_byte[i] = true;
    for (std::size_t i = 0; i < 896; ++i)
      if (!value_byte[i]) {
        ASSERT_EQ(zero[i], other[i]) << "layout byte " << i << " differs, seed " << seed;
      }
    // And the values really are at those bytes: Position[10] (LKneePitch).
    // Before Position: Accelerometer 3, Angles 2, Battery 4, Current 25, FSR 8, Gyroscope 3.
    const std::size_t knee = layout.floats[45 + LKneePitch];
    const SensorPacket p = randomPacket(seed);
    std::uint32_t bits = (std::uint32_t(other[knee + 1]) << 24) | (std::uint32_t(other[knee + 2]) << 16) |
                         (std::uint32_t(other[knee + 3]) << 8) | other[knee + 4];
    float read;
    std::memcpy(&read, &bits, 4);
    EXPECT_EQ(read, p.position[LKneePitch]);
  }
  // Two fixed points of the layout: Accelerometer[0]'s marker follows
  // RobotConfig (68 bytes with the map byte), its own 14-byte key and the
  // fixarray byte; Status's 25 fixints end the packet after its array16 header.
  EXPECT_EQ(layout.floats[0], 83u);
  EXPECT_EQ(zero[82], 0x93);
  EXPECT_EQ(layout.status.front(), 871u);
  EXPECT_EQ(zero[868], 0xdc);
  EXPECT_EQ(zero[869], 0x00);
  EXPECT_EQ(zero[870], 25);
}

TEST(SensorPacket, RoundTrips) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const SensorPacket p = randomPacket(seed);
    const PacketBytes b = encodeSensorPacket(p);
    std::string error;
    const auto q = decodeSensorPacket(b.data(), b.size(), &error);
    ASSERT_TRUE(q) << error;
    EXPECT_EQ(q->position, p.position);
    EXPECT_EQ(q->stiffness, p.stiffness);
    EXPECT_EQ(q->temperature, p.temperature);
    EXPECT_EQ(q->current, p.current);
    EXPECT_EQ(q->status, p.status);
    EXPECT_EQ(q->battery, p.battery);
    EXPECT_EQ(q->accelerometer, p.accelerometer);
    EXPECT_EQ(q->gyroscope, p.gyroscope);
    EXPECT_EQ(q->angles, p.angles);
    EXPECT_EQ(q->sonar, p.sonar);
    EXPECT_EQ(q->fsr, p.fsr);
    EXPECT_EQ(q->touch, p.touch);
    EXPECT_EQ(q->robot_config, p.robot_config);
  }
}

TEST(SensorPacket, DecoderRefusesOtherLayoutsNamingTheByte) {
  PacketBytes b = encodeSensorPacket(SensorPacket{});
  std::string error;
  EXPECT_FALSE(decodeSensorPacket(b.data(), 895, &error));
  EXPECT_NE(error.find("size 895"), std::string::npos) << error;
  b[83] = 0xcb;  // Accelerometer[0] as a float64 marker
  EXPECT_FALSE(decodeSensorPacket(b.data(), b.size(), &error));
  EXPECT_NE(error.find("byte 83"), std::string::npos) << error;
  EXPECT_NE(error.find("Accelerometer"), std::string::npos) << error;
}

TEST(SensorPacket, RobotConfigCheck) {
  EXPECT_EQ(checkRobotConfig(SensorPacket{}.robot_config), "");
  const std::string e = checkRobotConfig({"SHORT", "6.0.0", "SIMSWIFT000000HEAD00", "6.0.0"});
  EXPECT_NE(e.find("body id"), std::string::npos) << e;
  EXPECT_NE(e.find("20 characters"), std::string::npos) << e;
  EXPECT_NE(checkRobotConfig({"SIMSWIFT000000BODY00", "x.0.0", "SIMSWIFT000000HEAD00", "6.0.0"}), "");
}
