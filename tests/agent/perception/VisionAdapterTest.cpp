// The vision adapter: detections become robot-relative measurements; the
// closest ball wins; nothing while fallen.
#include <gtest/gtest.h>

#include <cmath>

#include "agent/perception/VisionAdapter.hpp"

namespace bb = agent::blackboard;
namespace al = common::libagent;

namespace {
al::Observation obs(al::ObservationType t, float x, float y, int team = -1) {
  al::Observation o{};
  o.type = t;
  o.x = x;
  o.y = y;
  o.distance = std::hypot(x, y);
  o.heading = std::atan2(y, x);
  o.team = team;
  return o;
}
}  // namespace

TEST(VisionAdapter, SplitsDetectionsForTheirConsumers) {
  bb::FrameInfo f;
  f.frame_index = 7;
  f.time = 0.25;
  f.observations[f.num_observations++] = obs(al::ObservationType::Ball, 2000, 100);
  f.observations[f.num_observations++] = obs(al::ObservationType::Ball, 900, -300);  // closer: wins
  f.observations[f.num_observations++] = obs(al::ObservationType::GoalPost, 3000, 800);
  f.observations[f.num_observations++] = obs(al::ObservationType::LineCorner, 1200, -400);
  f.observations[f.num_observations++] = obs(al::ObservationType::FieldLine, 700, 0);
  f.observations[f.num_observations++] = obs(al::ObservationType::Robot, 1500, 500, 2);
  // Given only as distance and heading.
  al::Observation polar{};
  polar.type = al::ObservationType::PenaltyCross;
  polar.distance = 1000;
  polar.heading = static_cast<float>(M_PI / 2);
  f.observations[f.num_observations++] = polar;
  const bb::VisionMeasurements v = agent::perception::adaptVision(f, false);
  EXPECT_EQ(v.frame_index, 7);
  ASSERT_TRUE(v.ball_seen);
  EXPECT_FLOAT_EQ(v.ball.x, 900);
  EXPECT_NEAR(v.ball.distance, std::hypot(900, 300), 1e-3);
  EXPECT_NEAR(v.ball.heading, std::atan2(-300, 900), 1e-6);
  ASSERT_EQ(v.num_features, 4);
  EXPECT_EQ(v.features[0].kind, bb::FeatureKind::GoalPost);
  EXPECT_EQ(v.features[1].kind, bb::FeatureKind::Corner);
  EXPECT_EQ(v.features[2].kind, bb::FeatureKind::LinePoint);
  EXPECT_EQ(v.features[3].kind, bb::FeatureKind::PenaltyCross);
  EXPECT_NEAR(v.features[3].where.x, 0, 1e-3);
  EXPECT_NEAR(v.features[3].where.y, 1000, 1e-3);
  ASSERT_EQ(v.num_robots, 1);
  EXPECT_EQ(v.robots[0].team, 2);
}

TEST(VisionAdapter, NothingWhileFallenOrBeyondRange) {
  bb::FrameInfo f;
  f.observations[f.num_observations++] = obs(al::ObservationType::Ball, 500, 0);
  f.observations[f.num_observations++] = obs(al::ObservationType::GoalPost, 9500, 0);  // beyond 9 m
  f.observations[f.num_observations++] = obs(al::ObservationType::GoalPost, NAN, 0);
  bb::VisionMeasurements v = agent::perception::adaptVision(f, false);
  EXPECT_TRUE(v.ball_seen);
  EXPECT_EQ(v.num_features, 0);
  v = agent::perception::adaptVision(f, true);
  EXPECT_FALSE(v.ball_seen);
  EXPECT_EQ(v.num_features, 0);
}

TEST(VisionAdapter, LinePiecesBecomePointsAndCornersKeepTheirShape) {
  bb::FrameInfo f;
  al::Observation line = obs(al::ObservationType::FieldLine, 1000, -600);
  line.x2 = 1000;
  line.y2 = 600;  // a 1.2 m piece across the view
  f.observations[f.num_observations++] = line;
  al::Observation corner = obs(al::ObservationType::LineCorner, 2000, 0);
  corner.corner = al::CornerKind::T;
  f.observations[f.num_observations++] = corner;
  const bb::VisionMeasurements v = agent::perception::adaptVision(f, false);
  // 1200 mm, points at most 400 mm apart: 4 points, ends included, then the corner.
  ASSERT_EQ(v.num_features, 5);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(v.features[i].kind, bb::FeatureKind::LinePoint);
    EXPECT_NEAR(v.features[i].where.x, 1000, 1e-3);
    EXPECT_NEAR(v.features[i].where.y, -600 + 400 * i, 1e-3);
  }
  EXPECT_EQ(v.features[4].kind, bb::FeatureKind::Corner);
  EXPECT_EQ(v.features[4].shape, bb::CornerShape::T);
}
