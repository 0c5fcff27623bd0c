// The SPL standard message (version 6) as bytes: round trip, the layout's
// offsets from the reference header, and malformed packets that must be
// rejected (never a crash), including thousands of random byte strings.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "agent/comms/SplMessage.hpp"
#include "agent/comms/TeamReceiver.hpp"

using namespace agent::comms;

namespace {

SplMessage sample(size_t data_bytes = 100) {
  SplMessage m;
  m.player = 3;
  m.team = 17;
  m.fallen = true;
  m.pose_x = -1234.5f;
  m.pose_y = 987.25f;
  m.pose_theta = 1.5f;
  m.walking_to_x = 100;
  m.walking_to_y = -200;
  m.shooting_to_x = 4500;
  m.shooting_to_y = 0;
  m.ball_age = 2.5f;
  m.ball_x = 350;
  m.ball_y = -40;
  m.ball_vel_x = -120;
  m.ball_vel_y = 15;
  m.suggestion = {0, 1, 2, 3, 4};
  m.intention = 3;
  m.average_walk_speed = 220;
  m.max_kick_distance = 5000;
  m.position_confidence = 80;
  m.side_confidence = 95;
  for (size_t i = 0; i < data_bytes; ++i) m.data.push_back(static_cast<uint8_t>(i * 7 + 1));
  return m;
}

float floatAt(const std::vector<uint8_t>& b, size_t at) {
  uint32_t u = b[at] | (b[at + 1] << 8) | (b[at + 2] << 16) | (static_cast<uint32_t>(b[at + 3]) << 24);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

}  // namespace

TEST(SplMessage, RoundTripKeepsEveryField) {
  const SplMessage m = sample();
  const std::vector<uint8_t> b = serialise(m);
  ASSERT_EQ(b.size(), kSplHeadBytes + 100);
  const ParseResult r = parse(b);
  ASSERT_TRUE(r.ok()) << parseErrorName(r.error);
  EXPECT_TRUE(r.message == m);
}

TEST(SplMessage, EmptyAndFullDataAreaRoundTrip) {
  for (size_t n : {size_t(0), size_t(1), kSplDataSize}) {
    const SplMessage m = sample(n);
    const auto b = serialise(m);
    EXPECT_EQ(b.size(), kSplHeadBytes + n);
    const ParseResult r = parse(b);
    ASSERT_TRUE(r.ok()) << n;
    EXPECT_TRUE(r.message == m) << n;
  }
}

// Offsets of the version-6 C struct (natural alignment, little-endian).
TEST(SplMessage, LayoutMatchesTheStandardMessageOffsets) {
  const auto b = serialise(sample(5));
  EXPECT_EQ(std::string(b.begin(), b.begin() + 4), "SPL ");
  EXPECT_EQ(b[4], 6);                    // version
  EXPECT_EQ(b[5], 3);                    // playerNum
  EXPECT_EQ(b[6], 17);                   // teamNum
  EXPECT_EQ(b[7], 1);                    // fallen
  EXPECT_EQ(floatAt(b, 8), -1234.5f);    // pose[0]
  EXPECT_EQ(floatAt(b, 16), 1.5f);       // pose[2]
  EXPECT_EQ(floatAt(b, 20), 100.f);      // walkingTo[0]
  EXPECT_EQ(floatAt(b, 28), 4500.f);     // shootingTo[0]
  EXPECT_EQ(floatAt(b, 36), 2.5f);       // ballAge
  EXPECT_EQ(floatAt(b, 40), 350.f);      // ball[0]
  EXPECT_EQ(floatAt(b, 52), 15.f);       // ballVel[1]
  EXPECT_EQ(b[56], 0);                   // suggestion[0]
  EXPECT_EQ(b[60], 4);                   // suggestion[4]
  EXPECT_EQ(b[61], 3);                   // intention
  EXPECT_EQ(b[62] | (b[63] << 8), 220);  // averageWalkSpeed
  EXPECT_EQ(b[64] | (b[65] << 8), 5000); // maxKickDistance
  EXPECT_EQ(b[66], 80);                  // currentPositionConfidence
  EXPECT_EQ(b[67], 95);                  // currentSideConfidence
  EXPECT_EQ(b[68] | (b[69] << 8), 5);    // numOfDataBytes
  EXPECT_EQ(b[70], 1);                   // data[0]
  EXPECT_EQ(kSplHeadBytes + kSplDataSize, 850u);
  EXPECT_EQ(kSplMaxPacketBytes, 852u);   // the C struct's sizeof (float alignment)
}

TEST(SplMessage, WholePaddedStructIsAccepted) {
  auto b = serialise(sample(10));
  b.resize(kSplMaxPacketBytes, 0);  // a team sending sizeof(struct)
  const ParseResult r = parse(b);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.message.data.size(), 10u);
}

TEST(SplMessage, SerialiseRejectsValuesTheWireCannotCarry) {
  SplMessage m = sample(kSplDataSize + 1);
  EXPECT_THROW(serialise(m), std::invalid_argument);
  m = sample();
  m.player = 6;
  EXPECT_THROW(serialise(m), std::invalid_argument);
  m.player = 1;
  m.team = 128;
  EXPECT_THROW(serialise(m), std::invalid_argument);
}

TEST(SplMessage, EveryTruncationIsRejected) {
  const auto b = serialise(sample(40));
  for (size_t n = 0; n < b.size(); ++n) {
    const ParseResult r = parse(b.data(), n);
    EXPECT_EQ(r.error, ParseError::TooShort) << n;
  }
  EXPECT_EQ(parse(nullptr, 0).error, ParseError::TooShort);
}

TEST(SplMessage, CorruptFieldsAreRejectedWithTheirReason) {
  const auto good = serialise(sample(8));
  auto with = [&](size_t at, uint8_t v) {
    auto b = good;
    b[at] = v;
    return parse(b).error;
  };
  EXPECT_EQ(with(0, 'X'), ParseError::BadHeader);
  EXPECT_EQ(with(3, '_'), ParseError::BadHeader);
  EXPECT_EQ(with(4, 7), ParseError::BadVersion);   // a 2018 (version 7) message
  EXPECT_EQ(with(5, 0), ParseError::BadPlayer);
  EXPECT_EQ(with(5, 6), ParseError::BadPlayer);
  EXPECT_EQ(with(6, 0xff), ParseError::BadTeam);   // int8 -1
  EXPECT_EQ(with(7, 2), ParseError::BadFallen);
  auto nan = good;
  const float q = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan[8], &q, 4);  // pose x
  EXPECT_EQ(parse(nan).error, ParseError::NonFinite);
  auto big = good;
  big[68] = 0x0d;  // numOfDataBytes = 781
  big[69] = 0x03;
  EXPECT_EQ(parse(big).error, ParseError::BadDataSize);
  auto more = good;
  more[68] = 9;  // claims one byte more than sent
  EXPECT_EQ(parse(more).error, ParseError::TooShort);
  std::vector<uint8_t> huge(kSplMaxPacketBytes + 1, 0);
  std::memcpy(huge.data(), "SPL ", 4);
  EXPECT_EQ(parse(huge).error, ParseError::TooLong);
}

// Thousands of random byte strings and of randomly corrupted good packets:
// never a crash, every packet accounted for, garbage never accepted.
TEST(SplMessage, RandomBytesAreCountedAndDropped) {
  std::mt19937_64 rng(20171);
  TeamReceiver rx(17, 1);
  std::vector<ReceivedPacket> batch;
  int64_t random_accepted = 0;
  for (int i = 0; i < 5000; ++i) {
    std::vector<uint8_t> b(rng() % 900);
    for (auto& x : b) x = static_cast<uint8_t>(rng());
    if (parse(b).ok()) ++random_accepted;
    batch.push_back({b, 0});
  }
  EXPECT_EQ(random_accepted, 0);  // would need "SPL ", version 6 and more by chance
  const auto good = serialise(sample(64));
  int64_t mutated_ok = 0;
  for (int i = 0; i < 5000; ++i) {
    auto b = good;
    const int flips = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < flips; ++k) b[rng() % b.size()] = static_cast<uint8_t>(rng());
    if (rng() % 4 == 0) b.resize(rng() % (b.size() + 1));
    const ParseResult r = parse(b);
    if (r.ok()) {
      ++mutated_ok;
      EXPECT_LE(r.message.data.size(), kSplDataSize);
      EXPECT_GE(r.message.player, 1);
      EXPECT_LE(r.message.player, kSplMaxPlayers);
    }
    batch.push_back({b, 0});
  }
  rx.receive(batch, 1000000);
  const TeamReceiverStats& s = rx.stats();
  EXPECT_EQ(s.received, 10000);
  EXPECT_EQ(s.accepted + s.malformed + s.other_team + s.own, s.received);
  EXPECT_GE(s.malformed, 5000);  // at least every random string
  EXPECT_GT(mutated_ok, 0);      // flips inside data/floats stay well-formed
}
