// The one seed derivation: SplitMix64 of parent XOR tag, chained per level;
// distinct tags (and orders of tags) give distinct children (that the tags of
// one parent's children are distinct is a static_assert in the header).
#include <gtest/gtest.h>

#include <cstdint>
#include <set>

#include "common/random/DeriveSeed.hpp"

namespace {

using common::random::deriveSeed;

TEST(DeriveSeed, IsSplitMix64OfParentXorTag) {
  // SplitMix64's published first output for state 0 (Vigna's splitmix64.c).
  EXPECT_EQ(deriveSeed(0, 0), 0xe220a8397b1dcdafULL);
  EXPECT_EQ(deriveSeed(5, 3), deriveSeed(6, 0));  // 5 ^ 3 == 6: the recipe is the XOR, then the mix
  EXPECT_NE(deriveSeed(5, 3), deriveSeed(5, 4));
}

TEST(DeriveSeed, ChainsKeepTheOrderOfTheirTags) {
  EXPECT_NE(deriveSeed(deriveSeed(7, 1), 2), deriveSeed(deriveSeed(7, 2), 1));
  std::set<uint64_t> children;
  for (uint64_t a = 0; a < 32; ++a)
    for (uint64_t b = 0; b < 32; ++b) children.insert(deriveSeed(deriveSeed(7, a), b));
  EXPECT_EQ(children.size(), 32u * 32u);
}

}  // namespace
