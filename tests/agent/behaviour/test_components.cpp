// Each DistributionComponent's update against hand-computed values
// (thesis 4.2.1.1), and the CompositeDistributionGenerator's order.
#include <gtest/gtest.h>

#include <cmath>

#include "agent/behaviour/BallPosComponent.hpp"
#include "agent/behaviour/CompositeDistributionGenerator.hpp"
#include "agent/behaviour/EntropyComponent.hpp"
#include "agent/behaviour/FlipFilterComponent.hpp"
#include "agent/behaviour/PenalisedComponent.hpp"
#include "agent/behaviour/RobotPosComponent.hpp"

using namespace agent::behaviour;

TEST(BallPosComponent, RaisesTheSightedSegment) {
  PositionalDistribution d;
  BehaviourInputs in;
  in.ball.seen_now = true;
  in.ball.field = {2250, 0};  // segment 6
  BallPosComponent c(5.0);
  c.apply(d, in, 0.1);  // adds 0.5: (1/9 + 0.5) / 1.5
  EXPECT_NEAR(d.probability(5), 0.407407407, 1e-8);
  EXPECT_NEAR(d.probability(0), 0.074074074, 1e-8);
  in.ball.seen_now = false;  // not seen: unchanged
  const auto before = d.probabilities();
  c.apply(d, in, 0.1);
  EXPECT_EQ(d.probabilities(), before);
}

TEST(EntropyComponent, ConvergesTowardUniform) {
  PositionalDistribution d;
  d.set({1, 0, 0, 0, 0, 0, 0, 0, 0});
  EntropyComponent c(0.01);
  c.apply(d, BehaviourInputs{}, 10.0);
  // alpha = 1 - exp(-0.1) = 0.0951626; 1 - alpha * 8/9 and alpha / 9.
  EXPECT_NEAR(d.probability(0), 0.9154110, 1e-6);
  EXPECT_NEAR(d.probability(8), 0.0105736, 1e-6);
  for (int i = 0; i < 2000; ++i) c.apply(d, BehaviourInputs{}, 10.0);  // long after: uniform
  EXPECT_NEAR(d.probability(0), 1.0 / 9, 1e-6);
}

TEST(RobotPosComponent, LowersTheRobotsSegmentWhileBallUnseen) {
  PositionalDistribution d;
  BehaviourInputs in;
  in.self.pose = {-3250, 3000, 0};  // segment 1
  RobotPosComponent c(0.3);
  c.apply(d, in, 1.0);  // exp(-0.3) = 0.740818: 0.740818 / 8.740818 and 1 / 8.740818
  EXPECT_NEAR(d.probability(0), 0.0847539, 1e-6);
  EXPECT_NEAR(d.probability(1), 0.1144058, 1e-6);
  in.ball.seen_now = true;  // the ball is in view: no evidence against the segment
  const auto before = d.probabilities();
  c.apply(d, in, 1.0);
  EXPECT_EQ(d.probabilities(), before);
}

TEST(FlipFilterComponent, ResetsOnFlipOrLowConfidence) {
  PositionalDistribution d;
  d.add(2, 1.0);
  BehaviourInputs in;
  FlipFilterComponent c(0.3);
  c.apply(d, in, 0.1);
  EXPECT_GT(d.probability(2), 0.5);  // no flip: unchanged
  in.self.flipped = true;
  c.apply(d, in, 0.1);
  EXPECT_DOUBLE_EQ(d.probability(2), 1.0 / 9);
  d.add(2, 1.0);
  in.self.flipped = false;
  in.self.confidence = 0.2;
  c.apply(d, in, 0.1);
  EXPECT_DOUBLE_EQ(d.probability(2), 1.0 / 9);
}

TEST(PenalisedComponent, ResetsWhilePenalised) {
  PositionalDistribution d;
  d.add(7, 3.0);
  BehaviourInputs in;
  PenalisedComponent c;
  c.apply(d, in, 0.1);
  EXPECT_GT(d.probability(7), 0.5);
  in.game.penalised = true;
  c.apply(d, in, 0.1);
  for (int j = 0; j < 9; ++j) EXPECT_DOUBLE_EQ(d.probability(j), 1.0 / 9);
}

TEST(CompositeDistributionGenerator, DefaultHasTheFiveComponentsInOrder) {
  auto g = CompositeDistributionGenerator::makeDefault(BehaviourConfig{});
  const char* want[] = {"PenalisedComponent", "FlipFilterComponent", "EntropyComponent",
                        "BallPosComponent", "RobotPosComponent"};
  ASSERT_EQ(g->components().size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_STREQ(g->components()[i]->name(), want[i]);
}

TEST(CompositeDistributionGenerator, OneTickByHand) {
  BehaviourConfig c;
  c.distribution.entropy_rate = 0.0;  // isolate ball and robot
  auto g = CompositeDistributionGenerator::makeDefault(c);
  BehaviourInputs in;
  in.self.pose = {-3000, 2000, 0};  // segment 1
  in.ball.seen_now = true;
  in.ball.field = {3000, -2000};  // segment 9
  g->update(in, 0.1);  // ball: +0.5 on segment 9; robot: no change (ball seen)
  EXPECT_NEAR(g->distribution().probability(8), 0.407407407, 1e-8);
  in.ball.seen_now = false;
  g->update(in, 1.0);  // segment 1 (0.0740741) x exp(-0.3), renormalised
  const double p1 = 0.0740741 * std::exp(-0.3);
  EXPECT_NEAR(g->distribution().probability(0), p1 / (1 - 0.0740741 + p1), 1e-6);
  in.game.penalised = true;  // penalised: back to uniform (then RobotPos acts)
  g->update(in, 0.0);
  EXPECT_NEAR(g->distribution().probability(8), 1.0 / 9, 1e-12);
}
