// The actuator stream: any subset of keys, several maps per cycle, maps
// split across reads, garbage refused with a clear error.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <msgpack.hpp>

#include "sim/lola/ActuatorDecoder.hpp"

using namespace simswift::lola;

namespace {

ActuatorCommand fullCommand(float base) {
  ActuatorCommand c;
  c.position.emplace();
  c.stiffness.emplace();
  for (int i = 0; i < kNumJoints; ++i) {
    (*c.position)[i] = base + 0.01f * i;
    (*c.stiffness)[i] = 0.5f;
  }
  c.chest = {{0.1f, 0.2f, 0.3f}};
  c.lfoot = {{0.4f, 0.5f, 0.6f}};
  c.rfoot = {{0.7f, 0.8f, 0.9f}};
  c.leye.emplace();
  c.reye.emplace();
  for (int i = 0; i < 24; ++i) (*c.leye)[i] = (*c.reye)[i] = i / 24.f;
  c.lear.emplace();
  c.rear.emplace();
  for (int i = 0; i < 10; ++i) (*c.lear)[i] = (*c.rear)[i] = i / 10.f;
  c.skull.emplace();
  for (int i = 0; i < 12; ++i) (*c.skull)[i] = i / 12.f;
  c.sonar = {{true, false}};
  return c;
}

ActuatorCommand only(ActuatorKey key, float value) {
  ActuatorCommand c;
  JointArray j;
  j.fill(value);
  switch (key) {
    case ActuatorKey::Position: c.position = j; break;
    case ActuatorKey::Stiffness: c.stiffness = j; break;
    case ActuatorKey::LEye: c.leye.emplace(); c.leye->fill(value); break;
    case ActuatorKey::Chest: c.chest = {{value, value, value}}; break;
    case ActuatorKey::Sonar: c.sonar = {{value != 0, value != 0}}; break;
    default: ADD_FAILURE() << "not used here";
  }
  return c;
}

bool feed(ActuatorDecoder& d, const std::string& bytes) { return d.feed(bytes.data(), bytes.size()); }

// A map from raw msgpack-c packing, for maps our encoder would not write.
template <typename T>
std::string packed(const T& value) {
  msgpack::sbuffer b;
  msgpack::pack(b, value);
  return std::string(b.data(), b.size());
}

}  // namespace

TEST(ActuatorDecoder, AllElevenKeysRoundTripAt786Bytes) {
  const ActuatorCommand c = fullCommand(0.25f);
  const std::string bytes = encodeActuatorMap(c);
  // The eleven keys of the public clients' actuator maps (B-Human's
  // NaoProvider, HULKs' hula), float32 values, Sonar as two booleans (as
  // HULKs sends it), in msgpack's format: a fixmap (1 byte), then key + array
  // header + 5 bytes a float: Position 9+3+125, Stiffness 10+3+125, Chest,
  // LFoot, RFoot 6+1+15 each, LEye, REye 5+3+120 each, LEar, REar 5+1+50
  // each, Skull 6+1+60, Sonar 6+1+2: 786 bytes.
  EXPECT_EQ(bytes.size(), 786u);
  ActuatorDecoder d;
  ASSERT_TRUE(feed(d, bytes)) << d.error();
  ASSERT_TRUE(d.hasAnswer());
  const ActuatorCommand got = d.takeAnswer();
  EXPECT_EQ(got.position, c.position);
  EXPECT_EQ(got.stiffness, c.stiffness);
  EXPECT_EQ(got.chest, c.chest);
  EXPECT_EQ(got.lfoot, c.lfoot);
  EXPECT_EQ(got.rfoot, c.rfoot);
  EXPECT_EQ(got.leye, c.leye);
  EXPECT_EQ(got.reye, c.reye);
  EXPECT_EQ(got.lear, c.lear);
  EXPECT_EQ(got.rear, c.rear);
  EXPECT_EQ(got.skull, c.skull);
  EXPECT_EQ(got.sonar, c.sonar);
  EXPECT_FALSE(d.hasAnswer());
}

TEST(ActuatorDecoder, PartialMapsAreMergedUntilAJointKeyCompletesTheCycle) {
  ActuatorDecoder d;
  ASSERT_TRUE(feed(d, encodeActuatorMap(only(ActuatorKey::LEye, 0.2f))));
  EXPECT_FALSE(d.hasAnswer());  // LEDs alone do not end a cycle
  ASSERT_TRUE(feed(d, encodeActuatorMap(only(ActuatorKey::LEye, 0.7f))));  // later wins
  ASSERT_TRUE(feed(d, encodeActuatorMap(only(ActuatorKey::Stiffness, 0.f))));
  ASSERT_TRUE(d.hasAnswer());
  const ActuatorCommand a = d.takeAnswer();
  ASSERT_TRUE(a.leye && a.stiffness);
  EXPECT_FLOAT_EQ((*a.leye)[3], 0.7f);
  EXPECT_FALSE(a.position);  // not sent: the body keeps what it had
  EXPECT_EQ(d.mapsDecoded(), 3u);
}

TEST(ActuatorDecoder, TwoMapsPerCycleAsRunswift2022SendsThem) {
  // Cycle 1: {Position, Stiffness, Chest} then {Sonar}; cycle 2 the same.
  ActuatorDecoder d;
  ActuatorCommand main1 = fullCommand(0.1f);
  main1.sonar.reset();
  main1.skull.reset();
  ActuatorCommand main2 = fullCommand(0.2f);
  main2.sonar.reset();
  main2.skull.reset();
  const std::string stream = encodeActuatorMap(main1) + encodeActuatorMap(only(ActuatorKey::Sonar, 1)) +
                             encodeActuatorMap(main2) + encodeActuatorMap(only(ActuatorKey::Sonar, 0));
  ASSERT_TRUE(feed(d, stream)) << d.error();
  ASSERT_TRUE(d.hasAnswer());
  const ActuatorCommand a1 = d.takeAnswer();
  EXPECT_FLOAT_EQ((*a1.position)[0], 0.1f);
  EXPECT_FALSE(a1.sonar);  // cycle 1's Sonar map came after its joint map
  ASSERT_TRUE(d.hasAnswer());
  const ActuatorCommand a2 = d.takeAnswer();
  EXPECT_FLOAT_EQ((*a2.position)[0], 0.2f);
  ASSERT_TRUE(a2.sonar);
  EXPECT_EQ(*a2.sonar, (std::array<bool, 2>{true, true}));
  EXPECT_FALSE(d.hasAnswer());
  // The last Sonar map waits for cycle 3's answer.
  ASSERT_TRUE(d.collecting().sonar);
  EXPECT_EQ(*d.collecting().sonar, (std::array<bool, 2>{false, false}));
}

TEST(ActuatorDecoder, AMapSplitAcrossReadsCompletesAtItsLastByte) {
  const std::string bytes = encodeActuatorMap(fullCommand(0.3f));
  for (std::size_t piece : {std::size_t(1), std::size_t(7), std::size_t(100)}) {
    ActuatorDecoder d;
    for (std::size_t at = 0; at < bytes.size(); at += piece) {
      EXPECT_FALSE(d.hasAnswer()) << "answer before byte " << at;
      ASSERT_TRUE(d.feed(bytes.data() + at, std::min(piece, bytes.size() - at))) << d.error();
    }
    ASSERT_TRUE(d.hasAnswer()) << "pieces of " << piece;
    EXPECT_FLOAT_EQ((*d.takeAnswer().position)[24], 0.3f + 0.24f);
  }
}

TEST(ActuatorDecoder, GenericPackersAreAccepted) {
  // rUNSWift packs std::map<std::string, std::vector<float>> (float32) and
  // std::vector<bool> for Sonar; other packers send doubles and integers.
  std::map<std::string, std::vector<double>> doubles{{"Position", std::vector<double>(25, 0.5)},
                                                     {"Chest", {1, 0, 0}}};
  std::map<std::string, std::vector<int>> ints{{"Stiffness", std::vector<int>(25, 1)}};
  ActuatorDecoder d;
  ASSERT_TRUE(feed(d, packed(doubles))) << d.error();
  ASSERT_TRUE(feed(d, packed(ints))) << d.error();
  ASSERT_TRUE(d.hasAnswer());
  EXPECT_FLOAT_EQ((*d.takeAnswer().position)[4], 0.5f);
  ASSERT_TRUE(d.hasAnswer());
  EXPECT_FLOAT_EQ((*d.takeAnswer().stiffness)[4], 1.f);
}

TEST(ActuatorDecoder, WrongLengthsKeysAndValuesAreRefusedNamingTheKey) {
  struct Case {
    std::string bytes;
    std::string expect;
  };
  std::map<std::string, std::vector<float>> short_position{{"Position", std::vector<float>(24, 0.f)}};
  std::map<std::string, std::vector<float>> unknown{{"RHipYawPitch", {0.f}}};
  std::map<std::string, std::vector<float>> nan{{"Stiffness", std::vector<float>(25, NAN)}};
  std::map<std::string, std::vector<double>> huge{{"Position", std::vector<double>(25, 1e300)}};
  std::map<std::string, std::vector<bool>> bool_position{{"Position", std::vector<bool>(25, true)}};
  std::map<std::string, float> scalar{{"Position", 1.5f}};
  std::map<int, std::vector<float>> int_key{{1, {0.f}}};
  const std::vector<Case> cases = {
      {packed(short_position), "key \"Position\": 24 values, LoLA takes 25"},
      {packed(unknown), "key \"RHipYawPitch\": not a LoLA actuator key"},
      {packed(nan), "key \"Stiffness\"[0]: a float, expected a finite number"},
      {packed(huge), "key \"Position\"[0]: a float, expected a finite number"},
      {packed(bool_position), "key \"Position\"[0]: a boolean"},
      {packed(scalar), "key \"Position\": expected an array, got a float"},
      {packed(int_key), "a key is an integer"},
      {packed(std::vector<float>{1.f}), "expected a map, got an array"},
  };
  for (const Case& c : cases) {
    ActuatorDecoder d;
    EXPECT_FALSE(feed(d, c.bytes));
    EXPECT_TRUE(d.failed());
    EXPECT_NE(d.error().find(c.expect), std::string::npos) << d.error();
    EXPECT_NE(d.error().find("map 1 (from byte 0)"), std::string::npos) << d.error();
    EXPECT_FALSE(feed(d, encodeActuatorMap(fullCommand(0))));  // refused until reset()
    d.reset();
    EXPECT_TRUE(feed(d, encodeActuatorMap(fullCommand(0))));
  }
}

TEST(ActuatorDecoder, GarbageIsAnErrorNeverACrash) {
  {
    ActuatorDecoder d;  // 0xc1: no msgpack value starts with it
    EXPECT_FALSE(feed(d, std::string("\xc1", 1)));
    EXPECT_NE(d.error().find("not a msgpack map"), std::string::npos) << d.error();
  }
  {
    // A map whose first key announces 4 GiB of text: msgpack-c waits for
    // the text; the byte limit ends the wait, nothing is allocated for it.
    ActuatorDecoder d;
    EXPECT_TRUE(feed(d, std::string("\x81\xdb\xff\xff\xff\xff", 6)));
    EXPECT_FALSE(d.hasAnswer());
    EXPECT_FALSE(feed(d, std::string(5000, 'x')));
    EXPECT_NE(d.error().find("no complete map within 4096 bytes"), std::string::npos) << d.error();
  }
  {
    ActuatorDecoder d;  // an array32 header of 4 G elements
    EXPECT_FALSE(feed(d, std::string("\xdd\xff\xff\xff\xff", 5)));
    EXPECT_NE(d.error().find("array size overflow"), std::string::npos) << d.error();
  }
  {
    ActuatorDecoder d;  // arrays nested 7 deep
    EXPECT_FALSE(feed(d, std::string("\x91\x91\x91\x91\x91\x91\x90", 7)));
    EXPECT_NE(d.error().find("depth size overflow"), std::string::npos) << d.error();
  }
  {
    ActuatorDecoder d;  // a 100-byte key (str8)
    EXPECT_FALSE(feed(d, std::string("\x81\xd9\x64", 3) + std::string(100, 'a') + std::string("\x90", 1)));
    EXPECT_NE(d.error().find("str size overflow"), std::string::npos) << d.error();
  }
  {
    // A valid map after a good one: the error names map 2 and where it starts.
    ActuatorDecoder d;
    const std::string good = encodeActuatorMap(only(ActuatorKey::Chest, 1));
    EXPECT_FALSE(feed(d, good + std::string("\x81\xa5Sonar\x92\xc0\xc0", 10)));
    EXPECT_NE(d.error().find("map 2 (from byte " + std::to_string(good.size()) + ")"), std::string::npos)
        << d.error();
    EXPECT_NE(d.error().find("key \"Sonar\"[0]: nil"), std::string::npos) << d.error();
  }
  // Seeded random bytes: every stream ends in an answer or an error, and the
  // decoder never holds more than its byte limit.
  // (Those not refused are waiting for the rest of an object.)
  std::mt19937 rng(7);
  int errors = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::string bytes(1 + rng() % 600, '\0');
    for (char& c : bytes) c = static_cast<char>(rng());
    ActuatorDecoder d;
    if (!feed(d, bytes)) ++errors;
    EXPECT_FALSE(d.hasAnswer()) << "trial " << trial;
    EXPECT_LE(d.bytesFed(), bytes.size());
  }
  EXPECT_GT(errors, 1800);  // seed 7: 1864 refused at once
}

TEST(ActuatorDecoder, AMapLargerThanTheLimitIsRefused) {
  DecoderOptions small;
  small.max_map_bytes = 500;
  ActuatorDecoder d(small);
  EXPECT_FALSE(feed(d, encodeActuatorMap(fullCommand(0))));  // 786 bytes, in one step
  EXPECT_NE(d.error().find("more than the limit of 500"), std::string::npos) << d.error();
  // A map within msgpack-c's per-object limits that is still far too large:
  // one key whose value is 64 arrays of 64 float64s (37 KB). Refused once
  // 4096 bytes have come without a complete map.
  ActuatorDecoder e;
  std::string endless("\x81\xa5" "Chest\xdc\x00\x40", 10);
  for (int i = 0; i < 64; ++i) {
    endless += std::string("\xdc\x00\x40", 3);
    for (int j = 0; j < 64; ++j) endless += std::string("\xcb\0\0\0\0\0\0\0\0", 9);
  }
  EXPECT_FALSE(feed(e, endless));
  EXPECT_NE(e.error().find("no complete map within 4096 bytes"), std::string::npos) << e.error();
  EXPECT_LE(e.bytesFed(), 4096u + 1024u);  // stopped within one step of the limit
}

TEST(ActuatorDecoder, AClientRunningAheadIsStopped) {
  ActuatorDecoder d;
  std::string ten;
  for (int i = 0; i < 10; ++i) ten += encodeActuatorMap(only(ActuatorKey::Position, 0.f));
  EXPECT_FALSE(feed(d, ten));
  EXPECT_NE(d.error().find("more than 8 answers ahead"), std::string::npos) << d.error();
}
