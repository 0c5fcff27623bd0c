// PositionalDistribution (thesis 4.2.1): grid, table 4.1's centres,
// normalisation after every update (hand-computed values), grid size from
// the reliable detection distance.
#include <gtest/gtest.h>

#include <numeric>

#include "agent/behaviour/PositionalDistribution.hpp"

using namespace agent::behaviour;

namespace {
double sum(const PositionalDistribution& d) {
  const auto& p = d.probabilities();
  return std::accumulate(p.begin(), p.end(), 0.0);
}
}  // namespace

TEST(PositionalDistribution, DefaultGridHasTable41Centres) {
  PositionalDistribution d;
  ASSERT_EQ(d.size(), 9);
  const double table41[9][2] = {{-3000, 2000}, {0, 2000},  {3000, 2000},
                                {-3000, 0},    {0, 0},     {3000, 0},
                                {-3000, -2000}, {0, -2000}, {3000, -2000}};
  for (int j = 0; j < 9; ++j) {
    EXPECT_DOUBLE_EQ(d.centre(j).x, table41[j][0]) << "segment " << j + 1;
    EXPECT_DOUBLE_EQ(d.centre(j).y, table41[j][1]) << "segment " << j + 1;
    EXPECT_EQ(d.segmentAt(d.centre(j)), j);
    EXPECT_DOUBLE_EQ(d.probability(j), 1.0 / 9);
  }
  // Table 5.2's ball 1 (2250, 0) is in segment 6, robot 2's start (-3250, 3000) in 1,
  // points off the field go to the nearest segment.
  EXPECT_EQ(d.segmentAt({2250, 0}), 5);
  EXPECT_EQ(d.segmentAt({-3250, 3000}), 0);
  EXPECT_EQ(d.segmentAt({5000, -3500}), 8);
}

TEST(PositionalDistribution, AddNormalises) {
  PositionalDistribution d;
  d.add(4, 0.5);  // (1/9 + 0.5) / 1.5 and (1/9) / 1.5
  EXPECT_NEAR(d.probability(4), (1.0 / 9 + 0.5) / 1.5, 1e-12);
  EXPECT_NEAR(d.probability(4), 0.407407407, 1e-8);
  EXPECT_NEAR(d.probability(0), 0.074074074, 1e-8);
  EXPECT_NEAR(sum(d), 1.0, 1e-12);
}

TEST(PositionalDistribution, ScaleNormalises) {
  PositionalDistribution d;
  d.scale(0, 0.5);  // 1/18 over 17/18 = 1/17; the others 2/17
  EXPECT_NEAR(d.probability(0), 1.0 / 17, 1e-12);
  EXPECT_NEAR(d.probability(3), 2.0 / 17, 1e-12);
  EXPECT_NEAR(sum(d), 1.0, 1e-12);
}

TEST(PositionalDistribution, BlendTowardUniform) {
  PositionalDistribution d(2, 1);
  d.set({0.8, 0.2});
  d.blendTowardUniform(0.25);  // 0.8 + 0.25 (0.5 - 0.8) = 0.725
  EXPECT_NEAR(d.probability(0), 0.725, 1e-12);
  EXPECT_NEAR(d.probability(1), 0.275, 1e-12);
}

TEST(PositionalDistribution, SetNormalisesAndDegenerateResets) {
  PositionalDistribution d(2, 2);
  d.set({1, 1, 2, 4});
  EXPECT_NEAR(d.probability(3), 0.5, 1e-12);
  EXPECT_NEAR(d.probability(0), 0.125, 1e-12);
  d.set({0, 0, 0, 0});  // no information left: uniform
  for (int j = 0; j < 4; ++j) EXPECT_DOUBLE_EQ(d.probability(j), 0.25);
  d.scale(2, 0.0);  // one segment ruled out: 1/3 for the others
  EXPECT_NEAR(d.probability(0), 1.0 / 3, 1e-12);
  EXPECT_NEAR(d.probability(2), 0.0, 1e-12);
  EXPECT_THROW(d.set({1, 2}), std::invalid_argument);
}

TEST(PositionalDistribution, GridFromReliableDetectionDistance) {
  // Half-diagonals (mm) on the 9000 x 6000 field: 3x2 -> 2121, 2x3 -> 2462,
  // 2x2 -> 2704, 3x3 -> 1803, 4x2 -> 1875, 5x2 -> 1749.
  EXPECT_EQ(PositionalDistribution::gridForDetection(9000, 6000, 2500), std::make_pair(3, 2));
  EXPECT_EQ(PositionalDistribution::gridForDetection(9000, 6000, 2000), std::make_pair(4, 2));
  EXPECT_EQ(PositionalDistribution::gridForDetection(9000, 6000, 1803.0), std::make_pair(3, 3));
  EXPECT_EQ(PositionalDistribution::gridForDetection(9000, 6000, 1800), std::make_pair(5, 2));
  GridConfig g;
  g.derive_from_detection = true;
  g.reliable_detection_distance = 2500;
  g.detection_margin = 500;  // 2000 -> 4 x 2
  const auto d = PositionalDistribution::fromConfig(g, FieldGeometry{});
  EXPECT_EQ(d.columns(), 4);
  EXPECT_EQ(d.rows(), 2);
  g.derive_from_detection = false;  // the configured 3 x 3
  EXPECT_EQ(PositionalDistribution::fromConfig(g, FieldGeometry{}).size(), 9);
}
