// Table 5.1's jittered start poses (harness/Table51Setup.hpp): the one seed
// recipe and the project's own draws, so docs/behaviour.md's kinematic table
// is the same on every compiler and standard library (issue 45, item 8).
#include <gtest/gtest.h>

#include <cmath>

#include "harness/Table51Setup.hpp"

using namespace agent::behaviour;
using namespace agent::behaviour::table51;

// Pinned against an independent implementation of the recipe (a few lines of
// Python's integers: SplitMix64 of parent ^ tag, chained; then
// Random::uniform's (z >> 11) * 2^-53, as common/random has them), not
// against this code's own output. Tolerance 1e-9 mm / rad: the arithmetic is
// the same double operations in both.
TEST(Table51Setup, JitterIsTheSeedRecipesOwnDraws) {
  const Pose2 a = jitter(kRobot2, 2, 1);
  EXPECT_NEAR(a.x, -3298.204232576753, 1e-9);
  EXPECT_NEAR(a.y, 2996.013215271559, 1e-9);
  EXPECT_NEAR(a.theta, -1.6315303417377436, 1e-9);
  const Pose2 b = jitter(kRobot3, 3, 1);  // y -3000 - 3.9: kept on the field
  EXPECT_NEAR(b.x, -1951.4492652256135, 1e-9);
  EXPECT_EQ(b.y, -3000.0);
  EXPECT_NEAR(b.theta, 1.7296138731310833, 1e-9);
  const Pose2 c = jitter(kRobot4, 4, 5);
  EXPECT_NEAR(c.x, -1655.289073945186, 1e-9);
  EXPECT_NEAR(c.y, 2943.1299789348445, 1e-9);
  EXPECT_NEAR(c.theta, -1.400995448370328, 1e-9);
}

TEST(Table51Setup, SeedZeroIsTheTableAndJitterStaysInItsRanges) {
  const Pose2 p = jitter(kRobot3, 3, 0);
  EXPECT_EQ(p.x, kRobot3.x);
  EXPECT_EQ(p.y, kRobot3.y);
  EXPECT_EQ(p.theta, kRobot3.theta);
  for (uint64_t seed = 1; seed <= 200; ++seed)
    for (const auto& [player, start] : {std::pair<int, Pose2>{2, kRobot2}, {3, kRobot3}, {4, kRobot4}}) {
      const Pose2 j = jitter(start, player, seed);
      EXPECT_LE(std::fabs(j.x - start.x), 150.0);
      EXPECT_LE(std::fabs(j.y - start.y), 150.0);
      EXPECT_LE(std::fabs(j.y), 3000.0);
      EXPECT_LE(std::fabs(j.theta - start.theta), 0.3);
    }
  // Two robots at one seed draw apart (each its own stream).
  EXPECT_NE(jitter(kRobot2, 2, 1).x - kRobot2.x, jitter(kRobot4, 4, 1).x - kRobot4.x);
}
