// SearchPayload: round trip through the packet's free data area, size
// limit, malformed input rejected (never a crash).
#include <gtest/gtest.h>

#include <random>

#include "agent/behaviour/SearchPayload.hpp"

using namespace agent::behaviour;

namespace {
SearchPayload sample() {
  SearchPayload p;
  p.player = 3;
  p.probabilities = {0.30, 0.10, 0.10, 0.10, 0.10, 0.10, 0.10, 0.05, 0.05};
  p.segment = 4;
  p.point = {0, -2000};
  return p;
}
}  // namespace

TEST(SearchPayload, RoundTrip) {
  const SearchPayload p = sample();
  const auto b = p.toBytes();
  EXPECT_EQ(b.size(), 13u + 2 * 9);
  std::string why;
  const auto q = SearchPayload::fromBytes(b, &why);
  ASSERT_TRUE(q) << why;
  EXPECT_EQ(q->player, 3);
  EXPECT_EQ(q->columns, 3);
  EXPECT_EQ(q->rows, 3);
  EXPECT_EQ(q->segment, 4);
  EXPECT_DOUBLE_EQ(q->point.x, 0);
  EXPECT_DOUBLE_EQ(q->point.y, -2000);
  ASSERT_EQ(q->probabilities.size(), 9u);
  for (int j = 0; j < 9; ++j) EXPECT_NEAR(q->probabilities[j], p.probabilities[j], 2.0 / 65535);
  SearchPayload none = sample();
  none.segment = -1;
  EXPECT_EQ(SearchPayload::fromBytes(none.toBytes())->segment, -1);
}

TEST(SearchPayload, LargestGridFitsTheFreeDataArea) {
  SearchPayload p;
  p.columns = 15;
  p.rows = 15;  // 225 segments: 463 bytes
  p.probabilities.assign(225, 1.0 / 225);
  p.segment = 224;
  const auto b = p.toBytes();
  EXPECT_LE(b.size(), SearchPayload::kMaxBytes);
  EXPECT_EQ(SearchPayload::fromBytes(b)->segment, 224);
  p.columns = 16;  // 240 segments do not fit
  p.probabilities.assign(240, 1.0 / 240);
  EXPECT_THROW(p.toBytes(), std::invalid_argument);
}

TEST(SearchPayload, MalformedIsRejected) {
  const auto good = sample().toBytes();
  std::string why;
  EXPECT_FALSE(SearchPayload::fromBytes(nullptr, 0, &why));
  auto b = good;
  b.pop_back();
  EXPECT_FALSE(SearchPayload::fromBytes(b, &why));
  EXPECT_EQ(why, "length does not match the grid");
  b = good;
  b[0] = 'X';
  EXPECT_FALSE(SearchPayload::fromBytes(b, &why));
  EXPECT_EQ(why, "bad magic");
  b = good;
  b[15] ^= 0x10;  // a probability byte
  EXPECT_FALSE(SearchPayload::fromBytes(b, &why));
  EXPECT_EQ(why, "bad checksum");
  b = good;
  b[4] = 0;  // zero columns
  EXPECT_FALSE(SearchPayload::fromBytes(b, &why));
  EXPECT_EQ(why, "bad grid size");
  // A segment out of range with a correct checksum.
  b = good;
  b[6] = 9;
  uint32_t s = 0;
  for (size_t i = 0; i + 2 < b.size(); ++i) s += b[i];
  b[b.size() - 2] = s & 0xff;
  b[b.size() - 1] = (s >> 8) & 0xff;
  EXPECT_FALSE(SearchPayload::fromBytes(b, &why));
  EXPECT_EQ(why, "segment out of range");
  std::vector<uint8_t> big(600, 0);
  EXPECT_FALSE(SearchPayload::fromBytes(big, &why));
  // Random bytes of every length up to the area: rejected or decoded, never a crash,
  // and anything decoded is a valid distribution.
  std::mt19937 rng(12);
  int accepted = 0;
  for (int n = 0; n <= 474; ++n) {
    std::vector<uint8_t> r(n);
    for (auto& x : r) x = static_cast<uint8_t>(rng());
    if (n >= 2) {
      r[0] = 'S';
      r[1] = 'B';
    }
    if (auto q = SearchPayload::fromBytes(r)) {
      ++accepted;
      EXPECT_EQ(static_cast<int>(q->probabilities.size()), q->columns * q->rows);
    }
  }
  EXPECT_LT(accepted, 3);
}
