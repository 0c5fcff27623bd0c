// SimpleUtilityCalculator, DistributedUtilityCalculator and SimpleStrategy
// (thesis 4.2.2) against hand calculations.
#include <gtest/gtest.h>

#include <cmath>

#include "agent/behaviour/DistributedUtilityCalculator.hpp"
#include "agent/behaviour/SimpleStrategy.hpp"
#include "agent/behaviour/SimpleUtilityCalculator.hpp"

using namespace agent::behaviour;

namespace {

BehaviourInputs at(double x, double y, double theta) {
  BehaviourInputs in;
  in.self.pose = {x, y, theta};
  return in;  // walk: 300 mm/s, 0.8 rad/s
}

Teammate heading(int player, int segment, bool penalised = false, double heard = 0.1) {
  Teammate t;
  t.player = player;
  t.penalised = penalised;
  t.time_since_heard = heard;
  SearchPayload p;
  p.segment = segment;
  p.probabilities.assign(9, 1.0 / 9);
  t.search = p;
  return t;
}

std::unique_ptr<SimpleStrategy> distributedStrategy() {
  StrategyConfig c;
  return std::make_unique<SimpleStrategy>(std::make_unique<DistributedUtilityCalculator>(
      std::make_unique<SimpleUtilityCalculator>(c), c));
}

}  // namespace

TEST(SimpleUtilityCalculator, TimeIncludesTheTurn) {
  StrategyConfig c;
  WalkLimits w;
  // Table 5.1's robot 2 at (-3250, 3000) facing +x, to segment 5's centre (0, 0):
  // distance hypot(3250, 3000) = 4422.952 mm -> 14.743172 s at 300 mm/s;
  // heading atan2(-3000, 3250) = -0.745419 rad -> 0.931774 s at 0.8 rad/s.
  const double t = SimpleUtilityCalculator::travelTime({-3250, 3000, 0}, {0, 0}, w, c);
  EXPECT_NEAR(t, 0.931774 + 14.743172, 1e-5);
  // To segment 1's centre (-3000, 2000): 1030.776 mm, -1.325818 rad.
  EXPECT_NEAR(SimpleUtilityCalculator::travelTime({-3250, 3000, 0}, {-3000, 2000}, w, c),
              1.325818 / 0.8 + 1030.776 / 300, 1e-5);
  // Within face_distance the turn does not count; never below min_travel_time.
  EXPECT_NEAR(SimpleUtilityCalculator::travelTime({0, -290, 3.0}, {0, 0}, w, c), 1.0, 1e-12);
  // Slower real walk, longer time.
  w.max_forward = 150;
  EXPECT_NEAR(SimpleUtilityCalculator::travelTime({0, 0, 0}, {3000, 0}, w, c), 20.0, 1e-12);
}

TEST(SimpleUtilityCalculator, UtilityIsProbabilityOverTime) {
  StrategyConfig c;
  SimpleUtilityCalculator u(c);
  PositionalDistribution d;
  EXPECT_NEAR(u.utility(d, 4, at(-3250, 3000, 0)), (1.0 / 9) / 15.674946, 1e-7);
  d.set({0, 0, 0, 0, 0.5, 0, 0, 0, 0.5});
  EXPECT_NEAR(u.utility(d, 4, at(-3250, 3000, 0)), 0.5 / 15.674946, 1e-7);
  EXPECT_DOUBLE_EQ(u.utility(d, 0, at(-3250, 3000, 0)), 0.0);
}

TEST(DistributedUtilityCalculator, TwoTeammatesOnSegment5DivideByThree) {
  StrategyConfig c;
  c.exclusive_segments = false;  // the thesis's formula alone (exclusivity: test_search_era.cpp)
  DistributedUtilityCalculator u(std::make_unique<SimpleUtilityCalculator>(c), c);
  SimpleUtilityCalculator local(c);
  PositionalDistribution d;
  BehaviourInputs in = at(-3250, 3000, 0);
  const double ul = local.utility(d, 4, in);
  EXPECT_NEAR(u.utility(d, 4, in), ul, 1e-15);  // nobody there: V = 0, divisor 1
  in.teammates = {heading(3, 4)};
  EXPECT_NEAR(u.utility(d, 4, in), ul / 2, 1e-15);
  in.teammates.push_back(heading(4, 4));
  // V_5 = 2 teammates; the divisor is V + 1 = 3 (see DistributedUtilityCalculator.hpp).
  EXPECT_EQ(u.visitors(d, 4, in), 2);
  EXPECT_NEAR(u.utility(d, 4, in), ul / 3, 1e-15);
  EXPECT_NEAR(u.utility(d, 0, in), local.utility(d, 0, in), 1e-15);  // other segments untouched
  // Penalised or silent teammates do not count.
  in.teammates.push_back(heading(5, 4, true));
  in.teammates.push_back(heading(6, 4, false, 10.0));
  EXPECT_NEAR(u.utility(d, 4, in), ul / 3, 1e-15);
}

TEST(SimpleStrategy, UniformPicksTheNearestSegment) {
  // Robot 2's start: segment 1 is 5.09 s away, every other one further.
  auto s = distributedStrategy();
  PositionalDistribution d;
  const SearchChoice c = s->choose(d, at(-3250, 3000, 0));
  EXPECT_EQ(c.segment, 0);
  EXPECT_DOUBLE_EQ(c.point.x, -3000);
  EXPECT_DOUBLE_EQ(c.point.y, 2000);
}

TEST(SimpleStrategy, ProbabilityAgainstDistance) {
  auto s = distributedStrategy();
  PositionalDistribution d;
  // Segment 9 at 0.5, the rest 0.0625; robot on segment 5's centre facing +x.
  d.set({0.0625, 0.0625, 0.0625, 0.0625, 0.0625, 0.0625, 0.0625, 0.0625, 0.5});
  // U5 = 0.0625 / 1 s (min time) = 0.0625; U9 = 0.5 / (3605.55/300 + 0.588003/0.8)
  // = 0.5 / 12.7535 = 0.0392: stay on 5.
  EXPECT_EQ(s->choose(d, at(0, 0, 0)).segment, 4);
  // Segment 5 searched (0.01): others 0.07; U9 = 0.0392 beats segment 2/8's
  // 0.07 / 8.63 = 0.0081 and segment 6's 0.07 / 10 = 0.007.
  d.set({0.07, 0.07, 0.07, 0.07, 0.01, 0.07, 0.07, 0.07, 0.5});
  const SearchChoice c = s->choose(d, at(0, 0, 0));
  EXPECT_EQ(c.segment, 8);
  EXPECT_NEAR(c.utilities[8], 0.5 / (std::hypot(3000, 2000) / 300 + 0.5880026 / 0.8), 1e-6);
}

TEST(SimpleStrategy, TeammatesHeadingThereChangeThePick) {
  auto s = distributedStrategy();
  PositionalDistribution d;
  // At (0, -1000) facing -y (uniform): segment 8 (0, -2000) straight ahead,
  // 1000 mm: 3.333 s, U = 0.03333; segment 5 behind: 3.333 + pi/0.8 = 7.2603 s,
  // U = 0.015304; every other segment below 0.0093.
  BehaviourInputs in = at(0, -1000, -kPi / 2);
  EXPECT_EQ(s->choose(d, in).segment, 7);
  // Two teammates heading to 8: 0.03333 / 3 = 0.01111 < 0.015304 -> 5.
  // (A divisor of 2 would give 0.01667 and keep 8.)
  in.teammates = {heading(3, 7), heading(4, 7)};
  const SearchChoice c = s->choose(d, in);
  EXPECT_EQ(c.segment, 4);
  EXPECT_NEAR(c.utilities[7], (1.0 / 9) / (1000.0 / 300) / 3, 1e-12);
  EXPECT_NEAR(c.utilities[4], (1.0 / 9) / (1000.0 / 300 + kPi / 0.8), 1e-12);
}
