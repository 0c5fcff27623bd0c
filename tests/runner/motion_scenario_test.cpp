// The scenario hook for Motion: a robot's `actions:` list (body actions over
// time and pushes) drives the ActionMotion inside the runner.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/runner/FallDetector.hpp"
#include "sim/runner/Runner.hpp"

using simswift::runner::FallDetector;
using simswift::runner::Runner;
using simswift::runner::Scenario;

TEST(MotionScenario, ParsesActionsAndPushes) {
  const Scenario sc = Scenario::parse(
      "robots:\n"
      "  - team: 0\n"
      "    player: 2\n"
      "    actions:\n"
      "      - {t: 0.5, action: walk, forward: 200, left: -50, turn: 0.3}\n"
      "      - {t: 3, push: {x: 1.5, y: -0.5}}\n"
      "      - {t: 2, action: kick, foot: left, power: 0.5, direction: 0.2}\n",
      "actions.yaml");
  ASSERT_EQ(sc.robots.size(), 1u);
  const auto& r = sc.robots[0];
  ASSERT_EQ(r.setup.actions.size(), 2u);
  EXPECT_EQ(r.setup.actions[0].body.type, agent::blackboard::ActionType::WALK);
  EXPECT_FLOAT_EQ(r.setup.actions[0].body.forward, 200);
  EXPECT_FLOAT_EQ(r.setup.actions[0].body.left, -50);
  EXPECT_FLOAT_EQ(r.setup.actions[0].body.turn, 0.3f);
  EXPECT_EQ(r.setup.actions[1].body.type, agent::blackboard::ActionType::KICK);
  EXPECT_EQ(r.setup.actions[1].body.foot, agent::blackboard::Foot::LEFT);
  EXPECT_FLOAT_EQ(r.setup.actions[1].body.kick_power, 0.5f);
  ASSERT_EQ(r.pushes.size(), 1u);
  EXPECT_DOUBLE_EQ(r.pushes[0].t_s, 3.0);
  EXPECT_DOUBLE_EQ(r.pushes[0].jx, 1.5);
}

TEST(MotionScenario, BadActionNamesTheLineAndKey) {
  try {
    Scenario::parse("robots:\n  - team: 0\n    player: 1\n    actions:\n      - {t: 1, action: dance}\n", "bad.yaml");
    FAIL() << "no error";
  } catch (const std::exception& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("bad.yaml:5"), std::string::npos) << msg;
    EXPECT_NE(msg.find("action"), std::string::npos) << msg;
  }
}

// End to end: the scenario walks the robot forward for 3 s, then a push
// knocks it over and it gets up again; the summary's robot line says so.
TEST(MotionScenario, ActionsWalkTheRobotAndPushesKnockItOver) {
  Scenario sc = Scenario::parse(
      "seed: 3\nrobots:\n"
      "  - team: 0\n    player: 1\n    x: -2.0\n"
      "    actions:\n"
      "      - {t: 0.5, action: walk, forward: 250}\n"
      "      - {t: 4.0, action: stand}\n"
      // 3.7 N*s: the momentum of the 3.5 m/s once added to the 1.05 kg torso.
      "      - {t: 6.0, push: {x: 3.7, y: 0}}\n",
      "walk.yaml");
  Runner runner(std::move(sc));
  runner.start();
  const int torso = runner.world().robot(0).model().rootLink();
  for (int i = 0; i < 550; ++i) runner.tick();
  const double x = runner.world().robot(0).linkPose(torso).translation().x();
  EXPECT_GT(x, -2.0 + 0.6);  // ~3 s at up to 250 mm/s (with the start ramp)
  EXPECT_GT(runner.world().robot(0).linkPose(torso).translation().z(), FallDetector::kStandHeight);  // still up
  // The run summary's per-robot line reports the same torso position.
  const simswift::runner::RunStats walked = runner.stats();
  ASSERT_EQ(walked.robots.size(), 1u);
  EXPECT_NEAR(walked.robots[0].x, x, 1e-9);
  EXPECT_NEAR(walked.robots[0].theta, 0.0, 0.3);  // walked straight ahead (rad)
  EXPECT_EQ(walked.robots[0].falls, 0);
  EXPECT_FALSE(walked.robots[0].down);
  EXPECT_EQ(walked.robotLines().rfind("  t0p1: x ", 0), 0u) << walked.robotLines();
  EXPECT_NE(walked.robotLines().find("falls 0  up\n"), std::string::npos) << walked.robotLines();
  for (int i = 0; i < 200; ++i) runner.tick();
  EXPECT_LT(runner.world().robot(0).linkPose(torso).translation().z(), FallDetector::kFallHeight);  // pushed over
  EXPECT_EQ(runner.stats().robots[0].falls, 1);
  EXPECT_TRUE(runner.stats().robots[0].down);
  EXPECT_NE(runner.stats().robotLines().find("falls 1  down\n"), std::string::npos) << runner.stats().robotLines();
  // It gets up by itself (auto get-up) within 10 s of the push.
  for (int i = 0; i < 800; ++i) runner.tick();
  EXPECT_FALSE(runner.stats().robots[0].down) << runner.stats().robotLines();
  EXPECT_EQ(runner.stats().robots[0].falls, 1);
}
