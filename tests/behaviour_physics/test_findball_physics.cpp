// The behaviours in physics, noise on (thesis 5.1's whole-field search):
// the 2017 ball searching component finds balls from table 5.1's robot 2
// start; three robots choose different segments; a penalty resets the
// distribution, stops the robot, and PLAYING releases it.
// Seeds: 301.. here (tests); bench_findball uses 1..5; 11 was used while
// writing the module (a tuning seed). Nothing in agent/ was tuned to them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "harness/FindBallHarness.hpp"

using simswift::runner::Runner;
using simswift::runner::Scenario;
namespace fh = findball_harness;
namespace bb = agent::blackboard;

class FindBall2017Physics : public ::testing::TestWithParam<int> {};

// Found = a robot sees the ball and is within 300 mm (thesis 5.1), within
// the thesis's 180 s; both by ground truth and on the robot's Blackboard.
TEST_P(FindBall2017Physics, OneRobotFindsTheBallWithin180s) {
  const int position = GetParam();
  Runner r(Scenario::parse(fh::scenario(1, "findball2017", position, 300 + position, 180), "find.yaml"));
  const fh::FindTimes t = fh::timeToFind(r, 180.0);
  std::printf("  table 5.2 position %d: found (ground truth) at %s s, (Blackboard) at %s s, falls %d\n", position,
              t.truth ? std::to_string(*t.truth).c_str() : "-", t.board ? std::to_string(*t.board).c_str() : "-",
              r.stats().falls);
  ASSERT_TRUE(t.truth) << "position " << position << ": not found by ground truth within 180 s";
  EXPECT_TRUE(t.board) << "position " << position << ": the robot's Blackboard never said found";
  EXPECT_LE(*t.truth, 180.0);
}

INSTANTIATE_TEST_SUITE_P(Table52, FindBall2017Physics, ::testing::Values(1, 2, 3, 5),
                         [](const auto& info) { return "Position" + std::to_string(info.param); });
// Position 2 (4000, -2500) was disabled while the robot's pose estimate
// jumped ~3 m near the centre circle: the detector reports the centre mark
// as a cross, like the penalty marks, and the robot's field model had no
// cross there, so a frame seeing only the centre mark re-localised the robot
// to a penalty mark (agent/localisation/FieldModel.cpp now lists it). Since
// then (with injected re-localisation poses at a low prior, Localiser.hpp
// inject_prior) position 2 is found in 150.5-164.1 s over seeds 1-6 (five
// of six in 150.5-151.3 s; tuning seeds, not this test's 302: 150.8 s), no
// jumps, worst pose error 66 mm.

// Three robots (table 5.1) with no ball on the field: the distributed
// utility sends them to different segments. Counted over the camera frames
// on which all three are heading to a segment.
TEST(FindBall2017ThreeRobots, ChosenSegmentsDifferInMostFrames) {
  Runner r(Scenario::parse(fh::scenario(3, "findball2017", 0, 311, 60), "three.yaml"));
  r.start();
  int64_t frames = 0, distinct = 0, last = -1;
  while (r.ticks() < 6000) {
    r.tick();
    const int64_t f = r.programs().program(0)->board().frame.read().frame_index;
    if (f == last) continue;
    last = f;
    int seg[3];
    bool all = true;
    for (int i = 0; i < 3; ++i) {
      seg[i] = r.programs().program(i)->board().findball.read().segment;
      all = all && seg[i] >= 0;
    }
    if (!all) continue;
    ++frames;
    if (seg[0] != seg[1] && seg[1] != seg[2] && seg[0] != seg[2]) ++distinct;
  }
  const double fraction = frames > 0 ? static_cast<double>(distinct) / frames : 0;
  std::printf("  three robots, 60 s, seed 311: segments pairwise different in %lld of %lld frames (%.1f %%)\n",
              static_cast<long long>(distinct), static_cast<long long>(frames), 100 * fraction);
  EXPECT_GT(frames, 1000);  // 60 s at 30 Hz, all three searching most of it
  EXPECT_GT(fraction, 0.5);  // "most"
}

// A penalty (15 s into the search, 10 s long): the local distribution is
// uniform again (PenalisedComponent), the robot stands where it was put,
// and when PLAYING resumes it searches (walks) again.
TEST(FindBall2017Penalty, PenaltyResetsTheDistributionStopsTheRobotAndReleases) {
  Runner r(Scenario::parse(
      fh::scenario(1, "findball2017", 0, 321, 40,
                   "game:\n  penalties: [{t: 15, robot: 0, penalty: player_pushing, duration: 10}]\n"),
      "pen.yaml"));
  r.start();
  auto fb = [&] { return r.programs().program(0)->board().findball.read(); };
  auto uniform = [](const bb::FindBallInfo& f) {
    for (double p : f.local)
      if (std::fabs(p - 1.0 / f.local.size()) > 1e-9) return false;
    return !f.local.empty();
  };
  while (r.ticks() < 1490) r.tick();
  const bb::FindBallInfo before = fb();
  EXPECT_FALSE(uniform(before)) << "15 s of search should have shaped the distribution";
  EXPECT_EQ(before.resets, 0);
  while (r.ticks() < 1600) r.tick();  // 16 s: penalised, at the sideline
  EXPECT_TRUE(r.programs().program(0)->board().game.read().penalised);
  EXPECT_TRUE(uniform(fb()));
  EXPECT_EQ(fb().resets, 1);
  EXPECT_STREQ(fb().activity, "penalised");
  EXPECT_EQ(r.programs().program(0)->board().motion_request.read().body.type, bb::ActionType::STAND);
  const simswift::game::PlanarPose p0 = simswift::game::robotPose(r.world(), 0);
  while (r.ticks() < 2450) r.tick();  // 24.5 s: still penalised
  EXPECT_TRUE(uniform(fb()));
  const simswift::game::PlanarPose p1 = simswift::game::robotPose(r.world(), 0);
  EXPECT_LT(std::hypot(p1.x - p0.x, p1.y - p0.y), 0.08);  // m: standing (the walk would cover 2 m)
  while (r.ticks() < 3100) r.tick();  // 31 s: released at 25 s
  EXPECT_FALSE(r.programs().program(0)->board().game.read().penalised);
  EXPECT_STRNE(fb().activity, "penalised");
  const simswift::game::PlanarPose p2 = simswift::game::robotPose(r.world(), 0);
  EXPECT_GT(std::hypot(p2.x - p1.x, p2.y - p1.y), 0.3);  // m: searching again
  EXPECT_FALSE(uniform(fb()));
}
