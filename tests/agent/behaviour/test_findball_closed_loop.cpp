// LOGIC TEST, not physics: the FindBall behaviours in closed loop with the
// kinematic stand-in of KinematicWorld.hpp (perfect walk integration, ball
// seen within 2500 mm and the camera's 60.9 deg field of view, no noise).
// The 2017 ball search finds table 5.2's balls 1, 2, 3 and 5 within 180 s
// from table 5.1's start; three robots mostly choose different segments
// (more than with the local utility alone); a penalty resets a robot's
// distribution; the 2016 FindBall starts at the search point nearest the
// last ball and visits the points in order. The same behaviours in the
// simulator, noise on: tests/behaviour_physics/test_findball_physics.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "harness/KinematicWorld.hpp"
#include "harness/Table51Setup.hpp"

using namespace agent::behaviour;

using namespace agent::behaviour::table51;

TEST(FindBallLogic, OneRobot2017FindsTable52Balls1235Within180s) {
  // Table 5.1's exact start (seed 0) and five jittered ones.
  for (int i : {1, 2, 3, 5})
    for (unsigned seed = 0; seed <= 5; ++seed) {
      const double t = findTime(BehaviourKind::FINDBALL_2017, 1, kBalls[i - 1], 180.0, seed);
      if (seed == 0) std::printf("2017, 1 robot, ball %d: found after %.1f s\n", i, t);
      EXPECT_LE(t, 180.0) << "ball position " << i << ", start seed " << seed;
    }
}

namespace {
// Fraction of ticks (all three searching) in which the three robots' chosen
// segments are pairwise different, over 120 s with the ball off the field.
double distinctFraction(bool distributed, int* ticks_out) {
  BehaviourConfig c = config(BehaviourKind::FINDBALL_2017);
  c.strategy.distributed = distributed;
  kin::World w;
  w.ball = {20000, 20000};
  w.add(2, kRobot2, c);
  w.add(3, kRobot3, c);
  w.add(4, kRobot4, c);
  int ticks = 0, distinct = 0;
  while (w.time < 120.0) {
    w.step();
    const int a = w.robots[0].behaviour->searchSegment();
    const int b = w.robots[1].behaviour->searchSegment();
    const int d = w.robots[2].behaviour->searchSegment();
    if (a < 0 || b < 0 || d < 0) continue;
    ++ticks;
    if (a != b && b != d && a != d) ++distinct;
  }
  *ticks_out = ticks;
  return static_cast<double>(distinct) / ticks;
}
}  // namespace

TEST(FindBallLogic, ThreeRobotsMostlyChooseDifferentSegments) {
  int ticks = 0, ticks_local = 0;
  const double fraction = distinctFraction(true, &ticks);
  const double local = distinctFraction(false, &ticks_local);
  std::printf("three robots, 120 s: chosen segments all different in %.2f %% of %d ticks "
              "(%.2f %% with the local SimpleUtilityCalculator only)\n",
              100 * fraction, ticks, 100 * local);
  EXPECT_GT(ticks, 3000);
  EXPECT_GT(fraction, 0.5);
  EXPECT_GT(fraction, local);  // the division by visitors is what spreads them
}

TEST(FindBallLogic, PenalisedRobotResetsItsDistribution) {
  kin::World w;
  w.ball = {20000, 20000};
  w.add(2, kRobot2, config(BehaviourKind::FINDBALL_2017));
  while (w.time < 30.0) w.step();
  const auto& d = w.robots[0].behaviour->findBall()->local;
  EXPECT_LT(d.probability(0), 0.05);  // segment 1 searched: unlikely now
  w.robots[0].penalised = true;
  w.step();
  for (int j = 0; j < 9; ++j)
    EXPECT_DOUBLE_EQ(w.robots[0].behaviour->findBall()->local.probability(j), 1.0 / 9);
  EXPECT_EQ(w.robots[0].last.request.body.type, agent::blackboard::ActionType::STAND);
  EXPECT_EQ(w.robots[0].last.payload->segment, -1);
}

TEST(FindBall2016Logic, StartsNearestTheLastBallThenVisitsInOrder) {
  const BehaviourConfig c;
  // Nearest to a ball last seen at (2500, 1800): point 4 (2000, 2000).
  EXPECT_EQ(FindBall2016::startIndex(c.search.points_2016, {2500, 1800}), 3);
  EXPECT_EQ(FindBall2016::startIndex(c.search.points_2016, {-3500, 0}), 0);
  EXPECT_EQ(FindBall2016::startIndex(c.search.points_2016, {-100, -1200}), 6);
  EXPECT_EQ(FindBall2016::nextIndex(7, 8), 0);

  // Closed loop: the robot saw the ball at (2500, 1800) once, it was then
  // taken away; the points visited must be 4, 5, 6, 7, 8, 1, 2, 3, 4. In the
  // stop_scan_spin style (it stops at 4 first; the era style passes through
  // 4 at once from beside the ball: test_search_era.cpp).
  kin::World w;
  w.ball = {2500, 1800};
  BehaviourConfig stop = config(BehaviourKind::FINDBALL_2016);
  stop.search2016.style = Search2016Style::STOP_SCAN_SPIN;
  w.add(2, {1000, 1500, 0}, stop);
  w.step();
  ASSERT_TRUE(w.robots[0].ever_seen);
  w.ball = {20000, 20000};
  std::vector<int> visited;
  while (w.time < 400.0 && visited.size() < 9) {
    w.step();
    const Point2 p = w.robots[0].behaviour->searchPoint();
    int idx = -1;
    for (int k = 0; k < 8; ++k)
      if (p.x == c.search.points_2016[k].x && p.y == c.search.points_2016[k].y) idx = k;
    if (idx >= 0 && (visited.empty() || visited.back() != idx + 1)) visited.push_back(idx + 1);
  }
  EXPECT_EQ(visited, (std::vector<int>{4, 5, 6, 7, 8, 1, 2, 3, 4}));
}
