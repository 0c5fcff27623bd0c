// The pass condition on hand-made truth (no physics): what each predicate
// reads, when each temporal operator decides, the first failure and its
// time, and the errors of a bad condition at file:line: key.
#include <gtest/gtest.h>

#include "app/scenario_tests/Condition.hpp"
#include "tests/support/ConfigErrors.hpp"

namespace {

using namespace simswift::scenario_tests;
using common::config::YamlReader;

const simswift::FieldConfig kField = simswift::FieldConfig::spl2017();

TimeNode condition(const std::string& yaml, int robots = 2, double limit = 60) {
  const YAML::Node root = YamlReader::parse(yaml, "t.yaml");
  return readCondition(YamlReader(root, "t.yaml"), "pass", robots, limit);
}

Truth truth(double t, double bx, double by) {
  Truth s;
  s.t = t;
  s.has_ball = true;
  s.ball_x = bx;
  s.ball_y = by;
  s.ball_z = 0.05;
  s.robots.resize(2);
  s.robots[0] = {0, -1.0, 0.0};
  s.robots[1] = {1, 1.0, 0.0};
  return s;
}

std::string errorOf(const std::string& yaml, int robots = 2) {
  return simswift::testing::configError([&] { condition(yaml, robots); });
}

TEST(BallInGoal, TheWholeBallOverTheLineBetweenThePosts) {
  // Goal line centre at x = 4.5, 5 cm wide; ball radius 5 cm: the whole
  // ball is over the line's outer edge beyond x = 4.5 + 0.025 + 0.05.
  EXPECT_FALSE(ballInGoal(truth(0, 4.57, 0), kField, 1));
  EXPECT_TRUE(ballInGoal(truth(0, 4.58, 0), kField, 1));
  EXPECT_FALSE(ballInGoal(truth(0, 4.58, 0), kField, 0));  // blue's goal is at -x
  EXPECT_TRUE(ballInGoal(truth(0, -4.7, 0.7), kField, 0));
  EXPECT_FALSE(ballInGoal(truth(0, -4.7, 0.8), kField, 0));  // beside the post (inner width 1.5 m)
}

TEST(Condition, WithinIsMetAtTheFirstTickThePredicateHolds) {
  const TimeNode c = condition("pass: {within: {seconds: 10, that: {ball_in_goal: red}}}");
  ConditionRun run(c, kField);
  EXPECT_EQ(run.update(truth(1, 0, 0)), Verdict3::Pending);
  EXPECT_EQ(run.update(truth(2, 4.6, 0)), Verdict3::True);
  EXPECT_DOUBLE_EQ(run.decidedAt(), 2);
}

TEST(Condition, WithinFailsAtItsDeadlineNamingItself) {
  const TimeNode c = condition("pass: {within: {seconds: 5, that: {ball_in_goal: red}}}");
  ConditionRun run(c, kField);
  EXPECT_EQ(run.update(truth(4.99, 0, 0)), Verdict3::Pending);
  EXPECT_EQ(run.update(truth(5.0, 0, 0)), Verdict3::False);
  EXPECT_DOUBLE_EQ(run.failureTime(), 5.0);
  EXPECT_NE(run.failure().find("ball_in_goal: red"), std::string::npos) << run.failure();
  EXPECT_NE(run.failure().find("not met by 5.00 s"), std::string::npos) << run.failure();
}

TEST(Condition, NeverBreaksAtTheTickItsPredicateHolds) {
  const TimeNode c = condition("pass: {all: [{eventually: {ball_in_goal: red}}, {never: {fallen: any}}]}");
  ConditionRun run(c, kField);
  Truth t = truth(1, 0, 0);
  EXPECT_EQ(run.update(t), Verdict3::Pending);
  t = truth(3.5, 0, 0);
  t.robots[1].fallen = true;
  EXPECT_EQ(run.update(t), Verdict3::False);
  EXPECT_DOUBLE_EQ(run.failureTime(), 3.5);
  EXPECT_NE(run.failure().find("broken at 3.50 s"), std::string::npos) << run.failure();
}

TEST(Condition, AGoalReachedEndsTheRunWithInvariantsHoldingSoFar) {
  const TimeNode c = condition("pass: {all: [{within: {seconds: 60, that: {touched_ball: 0}}}, {never: {fallen: 0}}]}");
  ConditionRun run(c, kField);
  Truth t = truth(1, 0, 0);
  EXPECT_EQ(run.update(t), Verdict3::Pending);
  t.t = 2;
  t.robots[0].touched_ball = true;
  EXPECT_EQ(run.update(t), Verdict3::True);
}

TEST(Condition, InvariantsAloneRunToTheTimeLimit) {
  const TimeNode c = condition("pass: {never: {robots_within: 0.5}}");
  ConditionRun run(c, kField);
  for (int k = 1; k <= 100; ++k) EXPECT_EQ(run.update(truth(0.1 * k, 0, 0)), Verdict3::Pending);
  EXPECT_EQ(run.finish(truth(10, 0, 0)), Verdict3::True);
}

TEST(Condition, AtEndReadsTheLastTruthOnly) {
  const TimeNode c = condition("pass: {at_end: {ball_in_zone: {x: [1, 2], y: [-1, 1]}}}");
  ConditionRun in(c, kField);
  EXPECT_EQ(in.update(truth(1, 0, 0)), Verdict3::Pending);  // out of the zone before the end: no matter
  EXPECT_EQ(in.finish(truth(60, 1.5, 0)), Verdict3::True);
  ConditionRun out(c, kField);
  EXPECT_EQ(out.update(truth(1, 1.5, 0)), Verdict3::Pending);
  EXPECT_EQ(out.finish(truth(60, 0, 0)), Verdict3::False);
  EXPECT_NE(out.failure().find("false at the end"), std::string::npos) << out.failure();
}

TEST(Condition, NotOfWithinFailsWhenItIsMet) {
  const TimeNode c = condition("pass: {not: {within: {seconds: 30, that: {ball_in_goal: blue}}}}");
  ConditionRun run(c, kField);
  EXPECT_EQ(run.update(truth(1, 0, 0)), Verdict3::Pending);
  EXPECT_EQ(run.update(truth(2, -4.7, 0)), Verdict3::False);
  EXPECT_NE(run.failure().find("it held at 2.00 s"), std::string::npos) << run.failure();
}

TEST(Condition, AnyPassesOnItsFirstMetBranch) {
  const TimeNode c = condition(
      "pass: {any: [{within: {seconds: 5, that: {ball_in_goal: red}}}, {within: {seconds: 9, that: {near_ball: "
      "{robot: 1, distance: 0.3}}}}]}");
  ConditionRun run(c, kField);
  EXPECT_EQ(run.update(truth(6, 0, 0)), Verdict3::Pending);  // the first branch failed, the second is open
  EXPECT_EQ(run.update(truth(7, 1.2, 0)), Verdict3::True);   // robot 1 at (1, 0): 0.2 m
}

TEST(Condition, FirstFailureIsTheEarliest) {
  const TimeNode c = condition(
      "pass: {all: [{never: {fallen: 1}}, {within: {seconds: 3, that: {ball_in_goal: red}}}]}");
  ConditionRun run(c, kField);
  EXPECT_EQ(run.update(truth(3, 0, 0)), Verdict3::False);
  EXPECT_NE(run.failure().find("not met by 3.00 s"), std::string::npos) << run.failure();
}

TEST(Condition, AnInvariantUnderAnyDecidesNothingEarly) {
  // Met at the first tick only if `never` counted as holding inside `any`.
  const TimeNode c = condition("pass: {any: [{eventually: {ball_in_goal: red}}, {never: {fallen: 0}}]}");
  ConditionRun run(c, kField);
  EXPECT_EQ(run.update(truth(0.01, 0, 0)), Verdict3::Pending);
  EXPECT_EQ(run.finish(truth(60, 0, 0)), Verdict3::True);  // nobody fell: the `never` branch holds
}

TEST(Condition, TheFailureNamedIsTheOneThatDecided) {
  // The `any` is met by its second branch at 30 s; its first branch failed
  // at 5 s but decided nothing. The fall at 40 s failed the condition.
  const TimeNode c = condition(
      "pass: {all: [{any: [{within: {seconds: 5, that: {ball_in_goal: red}}}, {within: {seconds: 60, that: "
      "{touched_ball: 1}}}]}, {never: {fallen: 0}}, {eventually: {ball_in_goal: blue}}]}");
  ConditionRun run(c, kField);
  Truth t = truth(5, 0, 0);
  EXPECT_EQ(run.update(t), Verdict3::Pending);
  t = truth(30, 0, 0);
  t.robots[1].touched_ball = true;
  EXPECT_EQ(run.update(t), Verdict3::Pending);
  t.t = 40;
  t.robots[0].fallen = true;
  EXPECT_EQ(run.update(t), Verdict3::False);
  EXPECT_NE(run.failure().find("fallen: 0"), std::string::npos) << run.failure();
  EXPECT_DOUBLE_EQ(run.failureTime(), 40);
}

TEST(Condition, OfTwoDecidingFailuresTheEarlierIsNamed) {
  const TimeNode c = condition(
      "pass: {any: [{within: {seconds: 8, that: {ball_in_goal: red}}}, {within: {seconds: 3, that: {touched_ball: 0}}}]}");
  ConditionRun run(c, kField);
  EXPECT_EQ(run.update(truth(3, 0, 0)), Verdict3::Pending);
  EXPECT_EQ(run.update(truth(8, 0, 0)), Verdict3::False);
  EXPECT_NE(run.failure().find("touched_ball: 0"), std::string::npos) << run.failure();
  EXPECT_DOUBLE_EQ(run.failureTime(), 3);
}

TEST(StatePredicates, SelectorsCountsAndSums) {
  Truth t = truth(1, 0, 0);
  t.robots[0].x = -0.2;  // blue, 0.2 m from the ball
  t.robots[1].x = 0.3;   // red, 0.3 m
  auto holds = [&](const std::string& p) {
    const TimeNode c = condition("pass: {at_end: " + p + "}");
    ConditionRun run(c, kField);
    return run.finish(t) == Verdict3::True;
  };
  EXPECT_TRUE(holds("{near_ball: {robot: any, distance: 0.35, count: 2}}"));
  EXPECT_FALSE(holds("{near_ball: {robot: blue, distance: 0.35, count: 2}}"));
  EXPECT_TRUE(holds("{near_ball: {robot: red, distance: 0.3}}"));
  EXPECT_FALSE(holds("{near_ball: {robot: 1, distance: 0.29}}"));
  EXPECT_TRUE(holds("{robots_within: 0.51}"));
  EXPECT_FALSE(holds("{robots_within: 0.5}"));
  t.robots[0].falls = 1;
  t.robots[1].falls = 2;
  EXPECT_TRUE(holds("{falls: {robot: any, at_least: 3}}"));
  EXPECT_FALSE(holds("{falls: {robot: blue, at_least: 2}}"));
  t.team_sent[0] = 40;
  EXPECT_TRUE(holds("{team_packets: {team: blue, at_most: 40}}"));
  EXPECT_FALSE(holds("{team_packets: {team: blue, at_most: 39}}"));
  EXPECT_TRUE(holds("{game_state: playing}"));
  EXPECT_FALSE(holds("{penalised: any}"));
  EXPECT_TRUE(holds("{time: {at_least: 1}}"));
  EXPECT_TRUE(holds("{near_pose: {robot: 0, x: 0, y: 0.1, distance: 0.25}}"));
  EXPECT_TRUE(holds("{all: [{not: {fallen: any}}, {any: [{touched_ball: 0}, {ball_in_zone: {x: [-1, 1], y: [-1, 1]}}]}]}"));
}

TEST(ConditionErrors, AStatePredicateNeedsATime) {
  const std::string e = errorOf("pass:\n  fallen: any\n");
  EXPECT_NE(e.find("t.yaml:2: pass.fallen: a state predicate needs a time"), std::string::npos) << e;
}

TEST(ConditionErrors, AMisspeltOperatorIsNamedWithAGuess) {
  const std::string e = errorOf("pass:\n  all:\n    - withn: {seconds: 3, that: {fallen: 0}}\n");
  EXPECT_NE(e.find("t.yaml:3"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean within"), std::string::npos) << e;
}

TEST(ConditionErrors, TwoOperatorsInOneMap) {
  const std::string e = errorOf("pass: {always: {fallen: 0}, never: {fallen: 1}}");
  EXPECT_NE(e.find("one operator per map"), std::string::npos) << e;
}

TEST(ConditionErrors, ARobotTheScenarioLacks) {
  const std::string e = errorOf("pass:\n  never:\n    fallen: 2\n");
  EXPECT_NE(e.find("t.yaml:3: pass.never.fallen: no robot 2 (the scenario has 2"), std::string::npos) << e;
}

TEST(ConditionErrors, WithinBeyondTheTimeLimitAndNesting) {
  EXPECT_NE(errorOf("pass: {within: {seconds: 61, that: {fallen: 0}}}").find("pass.within.seconds"), std::string::npos);
  const std::string nested = errorOf("pass: {always: {never: {fallen: 0}}}");
  EXPECT_NE(nested.find("a temporal operator cannot be inside another one"), std::string::npos) << nested;
  EXPECT_NE(errorOf("pass: {eventually: {ball_in_zone: {x: [2, 1], y: [0, 1]}}}").find("low <= high"),
            std::string::npos);
}

}  // namespace
