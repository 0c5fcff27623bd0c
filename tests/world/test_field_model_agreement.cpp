// The robot code's field model (agent/localisation/FieldModel) against the
// simulator's field (fields/spl_2017.yaml): same lines, circle, crosses and
// goal posts, so localisation is not wrong by construction.
#include <gtest/gtest.h>

#include <cmath>

#include "common/field/FieldFacts.hpp"
#include "agent/localisation/FieldModel.hpp"
#include "sim/world/FieldConfig.hpp"

namespace al = agent::localisation;
namespace bb = agent::blackboard;

TEST(FieldModelAgreement, RobotCodeFieldMatchesTheSimulatedField) {
  const simswift::FieldConfig f = simswift::FieldConfig::loadYaml(std::string(SIMSWIFT_SOURCE_DIR) +
                                                                  "/fields/spl_2017.yaml");
  const al::FieldModel m = al::FieldModel::spl2017();
  EXPECT_NEAR(m.length, f.length * 1000, 1e-6);
  EXPECT_NEAR(m.width, f.width * 1000, 1e-6);
  EXPECT_NEAR(m.line_width, f.line_width * 1000, 1e-6);
  // Every simulated line's ends lie on the model's lines, and vice versa.
  const auto lines = m.lines();
  for (const auto& l : f.lines)
    for (double t : {0.0, 0.5, 1.0}) {
      const al::Vec2 p{1000 * (l.ax + t * (l.bx - l.ax)), 1000 * (l.ay + t * (l.by - l.ay))};
      EXPECT_LT(al::distanceToLines(p, lines, m.centre_circle_radius), 1e-6) << p.x << ", " << p.y;
    }
  EXPECT_EQ(lines.size(), f.lines.size());
  ASSERT_EQ(f.circles.size(), 1u);
  EXPECT_NEAR(m.centre_circle_radius, f.circles[0].radius * 1000, 1e-6);
  // Crosses (the penalty marks and the centre mark: one cross detector sees
  // all three) and goal posts.
  int crosses = 0, posts = 0;
  for (const al::Landmark& l : m.landmarks()) {
    if (l.kind == bb::FeatureKind::PenaltyCross) {
      ++crosses;
      bool found = false;
      for (const auto& c : f.crosses) found |= std::hypot(c.x * 1000 - l.at.x, c.y * 1000 - l.at.y) < 1e-6;
      EXPECT_TRUE(found) << l.at.x;
    }
    if (l.kind == bb::FeatureKind::GoalPost) {
      ++posts;
      EXPECT_NEAR(std::fabs(l.at.x), f.length * 500, 1e-6);
      // Post centres: inner width plus one post diameter apart.
      EXPECT_NEAR(std::fabs(l.at.y), (f.goal.inner_width + f.goal.post_diameter) * 500, 1e-6);
    }
  }
  EXPECT_EQ(crosses, 3);
  EXPECT_EQ(f.crosses.size(), 3u);
  EXPECT_EQ(posts, 4);
}

// The shared field facts (common/field/FieldFacts.hpp) that the robot code's FieldModel
// does not carry: the carpet's border and the goal (mm against m).
TEST(FieldModelAgreement, FieldFactsMatchTheSimulatedField) {
  const simswift::FieldConfig f = simswift::FieldConfig::loadYaml(std::string(SIMSWIFT_SOURCE_DIR) +
                                                                  "/fields/spl_2017.yaml");
  EXPECT_NEAR(common::field::kBorderStripWidth, f.border * 1000, 1e-6);
  EXPECT_NEAR(common::field::kGoalPostDiameter, f.goal.post_diameter * 1000, 1e-6);
  EXPECT_NEAR(common::field::kGoalInnerWidth, f.goal.inner_width * 1000, 1e-6);
}
