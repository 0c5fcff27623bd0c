// Walk tests in physics (issue 3): the MotionModule drives the simulated NAO
// through the libagent block only. Seeded, noise on. Figures are printed so
// the achieved speeds can be read from the test log.
#include <gtest/gtest.h>

#include <cstdio>

#include "tests/runner/motion_harness.hpp"

using agent::blackboard::ActionType;
using motion_test::MotionHarness;

TEST(MotionPhysics, StandsStill) {
  MotionHarness h(1);
  h.request(ActionType::STAND);
  EXPECT_TRUE(h.run(3.0));
  const auto p = h.pose();
  std::printf("stand: torso z %.3f m, pose (%.3f, %.3f, %.3f)\n", h.torsoHeight(), p.x, p.y, p.theta);
  EXPECT_NEAR(p.x, -3.0, 0.05);
}

TEST(MotionPhysics, WalkForwardProbe) {
  MotionHarness h(1);
  h.request(ActionType::STAND);
  ASSERT_TRUE(h.run(1.0));
  const auto p0 = h.pose();
  h.request(ActionType::WALK, 300, 0, 0);
  bool ok = true;
  for (int i = 0; i < 10; ++i) {
    ok = h.run(1.0) && ok;
    const auto p = h.pose();
    std::printf("t %d: pose (%.3f, %.3f, %.3f) z %.3f posture %s odo %.0f\n", i + 1, p.x, p.y, p.theta,
                h.torsoHeight(), agent::blackboard::postureName(h.state().posture), h.state().odometry.forward);
  }
  const auto p1 = h.pose();
  std::printf("walk forward: %.3f m in 10 s (%.0f%% of 3 m)\n", p1.x - p0.x, (p1.x - p0.x) / 3.0 * 100);
  EXPECT_TRUE(ok);
}
