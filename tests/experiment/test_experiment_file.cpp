// Experiment files: the shipped ones load; every kind of bad file is refused
// with an error naming file, line and field, before any trial runs.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <sys/wait.h>

#include "app/experiment/Experiment.hpp"
#include "app/experiment/ThesisTables.hpp"
#include "app/experiment/BehaviourHooks.hpp"
#include "tests/experiment/ExperimentTestUtil.hpp"
#include "tests/support/ConfigErrors.hpp"

using namespace simswift;
using namespace simswift::experiment;

namespace {

// Line numbers matter: the tests below name them.
const std::string kGood =
    "name: t\n"                                        // 1
    "seed: 1\n"                                        // 2
    "time_limit: 10\n"                                 // 3
    "trials_per_position: 1\n"                         // 4
    "found: {distance: 0.3}\n"                         // 5
    "balls:\n"                                         // 6
    "  - {position: 1, x: 1.0, y: 0.0}\n"              // 7
    "setups:\n"                                        // 8
    "  - name: a\n"                                    // 9
    "    behaviour: script\n"                          // 10
    "    robots:\n"                                    // 11
    "      - {team: 19, player: 2, x: -1.0, y: 0.0, theta: 0.0, actions: [{t: 0, action: stand}]}\n"  // 12
    "      - {team: 19, player: 3, x: -1.0, y: 1.0, theta: 0.0, actions: [{t: 0, action: stand}]}\n";  // 13

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const size_t k = s.find(from);
  EXPECT_NE(k, std::string::npos) << from;
  if (k != std::string::npos) s.replace(k, from.size(), to);
  return s;
}

using exptest::experimentError;

void expectError(const std::string& text, const std::string& where, const std::string& what) {
  const std::string msg = experimentError(text);
  EXPECT_NE(msg.find(where), std::string::npos) << "message: " << msg << "\nexpected: " << where;
  EXPECT_NE(msg.find(what), std::string::npos) << "message: " << msg << "\nexpected: " << what;
}

}  // namespace

TEST(ExperimentFile, GoodFileLoads) {
  const Experiment e = Experiment::parse(kGood, "good.yaml");
  EXPECT_EQ(e.name, "t");
  EXPECT_EQ(e.numTrials(), 1);
  ASSERT_EQ(e.setups.size(), 1u);
  ASSERT_EQ(e.setups[0].robots.size(), 2u);
  EXPECT_EQ(e.setups[0].robots[1].player, 3);
  EXPECT_EQ(e.setups[0].robots[0].script.setup.actions.size(), 1u);
  EXPECT_DOUBLE_EQ(e.found.distance, 0.3);
  EXPECT_TRUE(e.found.sees);
  EXPECT_NO_THROW(checkBehaviours(e, behaviourHooks()));
}

TEST(ExperimentFile, UnknownKey) {
  expectError(replaced(kGood, "seed: 1\n", "seed: 1\nspeed: 3\n"), "bad.yaml:3:", "unknown key 'speed'");
  expectError(replaced(kGood, "found: {distance: 0.3}", "found: {distance: 0.3, seen: true}"), "bad.yaml:5:",
              "unknown key 'seen' in found");
}

TEST(ExperimentFile, BallOffTheCarpet) {
  // Carpet 10.4 x 7.4 m: |x| <= 5.2 - ball radius.
  expectError(replaced(kGood, "{position: 1, x: 1.0", "{position: 1, x: 5.19"), "bad.yaml:7: balls[0].x",
              "off the carpet");
}

TEST(ExperimentFile, RobotOffTheCarpet) {
  expectError(replaced(kGood, "player: 2, x: -1.0, y: 0.0", "player: 2, x: -1.0, y: -3.9"),
              "bad.yaml:12: setups[0].robots[0].y", "off the carpet");
}

TEST(ExperimentFile, RobotsOnTopOfEachOther) {
  expectError(replaced(kGood, "player: 3, x: -1.0, y: 1.0", "player: 3, x: -1.0, y: 0.2"),
              "bad.yaml:13: setups[0].robots[1].x", "stands on player 2");
}

TEST(ExperimentFile, MissingFields) {
  expectError(replaced(kGood, "time_limit: 10\n", ""), "bad.yaml", "time_limit: missing required key");
  expectError(replaced(kGood, "player: 3, x: -1.0, y: 1.0, theta: 0.0", "player: 3, x: -1.0, y: 1.0"),
              "bad.yaml:13: setups[0].robots[1].theta", "missing required key");
  expectError(replaced(kGood, "    behaviour: script\n", ""), "bad.yaml:11: setups[0].robots[0].behaviour",
              "missing");  // line 11: the line above went
}

// A misspelt key is named at its own line with the key it resembles, not
// reported as a missing key at the map's first line (issue 34 item 5): a
// required one (top level and in a robot), the setup's default behaviour
// (it was "missing" at the robot's line), one required only for a script
// robot, and an optional one.
TEST(ExperimentFile, MisspeltKeysAreNamedAtTheirLineWithTheNearestKey) {
  auto expectExactly = [](const std::string& text, const std::string& want) {
    const std::string msg = experimentError(text);
    EXPECT_EQ(msg, want) << text;
  };
  expectExactly(replaced(kGood, "trials_per_position: 1", "trials_per_positon: 1"),
                "bad.yaml:4: unknown key 'trials_per_positon' in <document> (did you mean trials_per_position? a "
                "required key, missing)");
  expectExactly(replaced(kGood, "player: 3, x: -1.0, y: 1.0, theta: 0.0", "player: 3, x: -1.0, y: 1.0, Theta: 0.0"),
                "bad.yaml:13: unknown key 'Theta' in setups[0].robots[1] (did you mean theta? a required key, "
                "missing)");
  expectExactly(replaced(kGood, "    behaviour: script\n", "    behavoiur: script\n"),
                "bad.yaml:10: unknown key 'behavoiur' in setups[0] (did you mean behaviour? a required key, "
                "missing)");
  const std::string robot0 = "theta: 0.0, actions: [{t: 0, action: stand}]}\n      - {team: 19, player: 3";
  const std::string no_actions = replaced(kGood, robot0, "theta: 0.0, acitons: [{t: 0, action: stand}]}\n"
                                                         "      - {team: 19, player: 3");
  expectExactly(no_actions, "bad.yaml:12: unknown key 'acitons' in setups[0].robots[0] (did you mean actions? a "
                            "required key, missing)");
  const std::string msg = experimentError(replaced(kGood, "found: {distance: 0.3}", "found: {distnace: 0.3}"));
  EXPECT_EQ(msg.rfind("bad.yaml:5: unknown key 'distnace' in found (did you mean distance?); expected one of ", 0),
            0u) << msg;
  // Short keys get no guess (x / y are both keys): still "missing".
  expectError(replaced(kGood, "player: 3, x: -1.0, y: 1.0", "player: 3, z: -1.0, y: 1.0"),
              "bad.yaml:13: setups[0].robots[1].x", "missing required key");
}

TEST(ExperimentFile, ZeroTimeLimit) {
  expectError(replaced(kGood, "time_limit: 10", "time_limit: 0"), "bad.yaml:3: time_limit", "must be > 0");
}

TEST(ExperimentFile, FoundDistanceBelowBallRadius) {
  expectError(replaced(kGood, "distance: 0.3", "distance: 0.04"), "bad.yaml:5: found.distance",
              "must be >= the ball radius 0.05");
}

// The found rule reads the robots' ball detections: vision that cannot see
// the ball is refused unless the rule does without them.
TEST(ExperimentFile, FoundRuleNeedsBallDetections) {
  const std::string off = replaced(kGood, "found: {distance: 0.3}\n",
                                   "found: {distance: 0.3, sees: true}\nvision: {ball: {enabled: false}}\n");
  expectError(off, "bad.yaml:5: found.sees", "needs the robots' ball detections");
  expectError(replaced(off, "distance: 0.3, sees: true", "distance: 0.3"), "bad.yaml:6: vision",
              "needs the robots' ball detections");
  EXPECT_EQ(experimentError(replaced(off, "sees: true", "sees: false")), "");
}

TEST(ExperimentFile, StartPenalisedRange) {
  expectError(replaced(kGood, "seed: 1\n", "seed: 1\nstart: {penalised: 0}\n"), "bad.yaml:3: start.penalised",
              "must be in [0.05, 60]");
  expectError(replaced(kGood, "seed: 1\n", "seed: 1\nstart: {penalized: 1}\n"), "bad.yaml:3:",
              "unknown key 'penalized'");
}

TEST(ExperimentFile, DuplicatePlayers) {
  expectError(replaced(kGood, "player: 3", "player: 2"), "bad.yaml:13: setups[0].robots[1].player",
              "team 19 player 2 appears twice");
}

TEST(ExperimentFile, UnknownBehaviourAndOverrides) {
  expectError(replaced(kGood, "behaviour: script", "behaviour: findball2018"), "bad.yaml:10: setups[0].behaviour",
              "expected one of");
  const std::string text =
      "name: t\nseed: 1\ntime_limit: 10\ntrials_per_position: 1\nballs:\n  - {position: 1, x: 1.0, y: 0.0}\n"
      "setups:\n  - name: a\n    config: {grid: 3}\n    behaviour: findball2017\n    robots:\n"
      "      - {team: 19, player: 2, x: -1.0, y: 0.0, theta: 0.0, config: {speed: 0.2}}\n";
  const Experiment e = Experiment::parse(text, "bad.yaml");
  // Overrides pass through opaque, the robot's on top of the setup's.
  EXPECT_EQ(e.setups[0].robots[0].config_yaml, "{grid: 3, speed: 0.2}");
}

TEST(ExperimentFile, ActionsOnlyForScriptRobots) {
  expectError(replaced(kGood, "    behaviour: script\n", "    behaviour: striker\n"), "bad.yaml:12: setups[0].robots[0].actions",
              "only a script robot takes actions");
}

// The behaviours an experiment takes are the robot program's table of kinds
// (agent/behaviour/BehaviourConfig.hpp) and script, listed in its errors.
TEST(ExperimentFile, BehaviourNamesComeFromTheKindsTable) {
  expectError(replaced(kGood, "    behaviour: script\n", ""), "bad.yaml:11: setups[0].robots[0].behaviour",
              "give the robot (or its setup) a behaviour: findball2016, findball2017, striker or script");
  expectError(replaced(kGood, "    behaviour: script\n", "    behaviour: findball2018\n"),
              "bad.yaml:10: setups[0].behaviour", "expected one of findball2016, findball2017, striker, script");
}

// The command line refuses a bad file with exit code 2 and runs nothing.
TEST(ExperimentFile, CommandExitsWithTwoBeforeAnyTrial) {
  const std::string dir = exptest::freshDir("cli");
  exptest::writeAll(dir + "/bad.yaml", replaced(kGood, "time_limit: 10", "time_limit: 0"));
  const std::string cmd = exptest::simswiftBinary() + " experiment '" + dir + "/bad.yaml' --out '" + dir +
                          "/out' > '" + dir + "/stderr.txt' 2>&1";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_NE(exptest::readAll(dir + "/stderr.txt").find("bad.yaml:3: time_limit: must be > 0"), std::string::npos)
      << exptest::readAll(dir + "/stderr.txt");
  EXPECT_FALSE(exptest::fileExists(dir + "/out"));
}

// The shipped thesis experiments load (their behaviours are refused until
// the behaviours land); the script one passes --check.
TEST(ExperimentFile, ShippedExperiments) {
  const std::string src = SIMSWIFT_SOURCE_DIR;
  const Experiment full = Experiment::loadFile(src + "/scenarios/thesis_findball.yaml");
  EXPECT_EQ(full.numTrials(), 200);  // 2 components x 10 positions x 10
  ASSERT_EQ(full.balls.size(), 10u);
  // Table 5.2 position 4 and table 5.1 robot 3 (mm in the thesis, m here).
  EXPECT_DOUBLE_EQ(full.balls[3].x, 4.5);
  EXPECT_DOUBLE_EQ(full.balls[3].y, 3.0);
  EXPECT_DOUBLE_EQ(full.time_limit, 180);
  EXPECT_DOUBLE_EQ(full.found.distance, 0.3);
  EXPECT_EQ(full.found.seen_frames, 5);  // the thesis's controller: ball_seen_count >= 5
  // Position 5 on the bottom touch line (the controller's -3 m; table 5.2 prints +3000).
  EXPECT_EQ(full.balls[4].number, 5);
  EXPECT_DOUBLE_EQ(full.balls[4].x, 2.25);
  EXPECT_DOUBLE_EQ(full.balls[4].y, -3.0);
  ASSERT_EQ(full.setups.size(), 2u);
  ASSERT_EQ(full.setups[0].robots.size(), 3u);
  EXPECT_EQ(full.setups[0].robots[1].player, 3);
  EXPECT_DOUBLE_EQ(full.setups[0].robots[1].x, -2.0);
  EXPECT_DOUBLE_EQ(full.setups[0].robots[1].y, -3.0);
  EXPECT_EQ(full.setups[0].thesis_table, "5.3");
  EXPECT_EQ(full.setups[1].thesis_table, "5.4");

  // Every ball and start point is the thesis's (tables 5.2 and 5.1).
  for (const BallPosition& b : full.balls) {
    const ThesisPoint& p = thesisBallPositions().at(b.number - 1);
    EXPECT_EQ(p.number, b.number);
    EXPECT_NEAR(b.x * 1000, p.x_mm, 1e-9) << "position " << b.number;
    EXPECT_NEAR(b.y * 1000, p.y_mm, 1e-9) << "position " << b.number;
  }
  for (const auto& s : full.setups)
    for (const ExperimentRobot& r : s.robots) {
      const ThesisPoint& p = thesisStartPoints().at(r.player - 2);
      EXPECT_NEAR(r.x * 1000, p.x_mm, 1e-9) << "player " << r.player;
      EXPECT_NEAR(r.y * 1000, p.y_mm, 1e-9) << "player " << r.player;
    }

  const Experiment real = Experiment::loadFile(src + "/scenarios/thesis_findball_real.yaml");
  for (const BallPosition& b : real.balls) {
    EXPECT_NEAR(b.x * 1000, thesisBallPositions().at(b.number - 1).x_mm, 1e-9);
    EXPECT_NEAR(b.y * 1000, thesisBallPositions().at(b.number - 1).y_mm, 1e-9);
  }
  // One robot: the top left corner, table 5.1's robot 2 (§5.1).
  EXPECT_EQ(real.setups[0].robots[0].player, 2);
  EXPECT_DOUBLE_EQ(real.setups[0].robots[0].x, -3.25);
  EXPECT_EQ(real.numTrials(), 100);  // (1 and 3 robots) x 2 components x 5 positions x 5
  ASSERT_EQ(real.setups.size(), 4u);
  EXPECT_EQ(real.setups[0].robots.size(), 1u);
  EXPECT_EQ(real.setups[2].robots.size(), 3u);

  const Experiment script = Experiment::loadFile(src + "/scenarios/findball_script.yaml");
  EXPECT_NO_THROW(checkBehaviours(script, behaviourHooks()));

  // The default (scripts/build-and-run.sh): a slice of the simulated
  // comparison, thesis positions and start points, both components.
  const Experiment quick = Experiment::loadFile(src + "/scenarios/findball_quick.yaml");
  EXPECT_EQ(quick.numTrials(), 30);
  ASSERT_EQ(quick.setups.size(), 2u);
  EXPECT_EQ(quick.setups[0].thesis_table, "5.3");
  EXPECT_EQ(quick.setups[1].thesis_table, "5.4");
  EXPECT_EQ(quick.setups[0].robots[0].behaviour, "findball2016");
  EXPECT_EQ(quick.setups[1].robots[0].behaviour, "findball2017");
  EXPECT_DOUBLE_EQ(quick.time_limit, full.time_limit);
  EXPECT_DOUBLE_EQ(quick.found.distance, full.found.distance);
  for (const BallPosition& b : quick.balls) {
    EXPECT_NEAR(b.x * 1000, thesisBallPositions().at(b.number - 1).x_mm, 1e-9) << "position " << b.number;
    EXPECT_NEAR(b.y * 1000, thesisBallPositions().at(b.number - 1).y_mm, 1e-9) << "position " << b.number;
  }
  for (size_t k = 0; k < quick.setups[0].robots.size(); ++k) {
    EXPECT_DOUBLE_EQ(quick.setups[0].robots[k].x, full.setups[0].robots[k].x);
    EXPECT_DOUBLE_EQ(quick.setups[0].robots[k].y, full.setups[0].robots[k].y);
  }
}

// The vision: block is the scenario's (read by sim/vision's reader): checked
// at load time, given to every trial's scenario.
TEST(ExperimentFile, VisionBlock) {
  const std::string with = replaced(kGood, "found: {distance: 0.3}\n",
                                    "found: {distance: 0.3}\nvision: {ball: {max_distance_mm: 1500}}\n");
  const Experiment e = Experiment::parse(with, "v.yaml");
  EXPECT_DOUBLE_EQ(trialScenario(e, trialSpec(e, 0)).vision[vision::Feature::Ball].max_distance_mm, 1500);
  expectError(replaced(with, "max_distance_mm: 1500", "max_distance: 1.5"), "bad.yaml:6:", "unknown key 'max_distance'");
}

// SPL team numbers go to the scenario as they are; the first team in a
// setup plays blue, a second red; a third team is refused.
TEST(ExperimentFile, TeamsAndColours) {
  const std::string two = replaced(kGood, "{team: 19, player: 3", "{team: 7, player: 3");
  const Experiment e = Experiment::parse(two, "two.yaml");
  const runner::Scenario sc = trialScenario(e, trialSpec(e, 0));
  ASSERT_EQ(sc.robots.size(), 2u);
  EXPECT_EQ(sc.robots[0].team, 19);
  EXPECT_EQ(sc.robots[1].team, 7);
  EXPECT_EQ(sc.robots[0].colour, runner::TeamColour::Blue);
  EXPECT_EQ(sc.robots[1].colour, runner::TeamColour::Red);
  const std::string three = replaced(two, "actions: [{t: 0, action: stand}]}\n      - {team: 7",
                                     "actions: [{t: 0, action: stand}]}\n      - {team: 8, player: 4, x: 1.0, "
                                     "y: 2.0, theta: 0, actions: [{t: 0, action: stand}]}\n      - {team: 7");
  expectError(three, "bad.yaml:12: setups[0].robots", "at most two team numbers");
  expectError(replaced(kGood, "team: 19, player: 2", "team: 300, player: 2"), "bad.yaml:12: setups[0].robots[0].team",
              "must be in [0, 255]");
}

// Trial numbering and seeds: a pure function of (seed, index), distinct.
TEST(ExperimentFile, TrialSpecs) {
  const Experiment e = Experiment::parse(exptest::tinyExperiment(3), "tiny.yaml");
  ASSERT_EQ(e.numTrials(), 6);
  const TrialSpec t4 = trialSpec(e, 4);
  EXPECT_EQ(t4.setup, 0);
  EXPECT_EQ(t4.ball, 1);
  EXPECT_EQ(t4.repeat, 1);
  EXPECT_EQ(trialSpec(e, 4).seed, t4.seed);
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) EXPECT_NE(trialSpec(e, i).seed, trialSpec(e, j).seed);
  EXPECT_LT(t4.seed, 2147483648ull);
  const runner::Scenario sc = trialScenario(e, t4);
  ASSERT_TRUE(sc.ball.has_value());
  EXPECT_DOUBLE_EQ(sc.ball->second, 1.5);
  EXPECT_EQ(sc.seed, t4.seed);
  // 1 s penalised (the default start), then the time limit.
  EXPECT_EQ(playTick(e), 100);
  EXPECT_DOUBLE_EQ(sc.duration, 1.0 + e.time_limit);
  ASSERT_EQ(sc.robots.size(), 1u);
  EXPECT_EQ(sc.robots[0].player, 2);
  EXPECT_EQ(sc.robots[0].setup.actions.size(), 1u);
  // findballexp's start: penalised from t = 0 (INITIAL), then PLAYING and
  // unpenalised at 1 s, left where they stand.
  EXPECT_EQ(sc.game.initial_state, common::libagent::GameStateValue::Initial);
  ASSERT_EQ(sc.game.timeline.size(), 1u);
  EXPECT_EQ(sc.game.timeline[0].state, common::libagent::GameStateValue::Playing);
  EXPECT_DOUBLE_EQ(sc.game.timeline[0].t_s, 1.0);
  ASSERT_EQ(sc.game.penalties.size(), 2u);
  EXPECT_DOUBLE_EQ(sc.game.penalties[0].t_s, 0.0);
  EXPECT_NE(sc.game.penalties[0].penalty, common::libagent::Penalty::None);
  EXPECT_LT(sc.game.penalties[0].duration_s, 0);  // until lifted
  EXPECT_DOUBLE_EQ(sc.game.penalties[1].t_s, 1.0);
  EXPECT_EQ(sc.game.penalties[1].penalty, common::libagent::Penalty::None);
  EXPECT_EQ(sc.game.on_unpenalise, game::GameConfig::Return::Sideline);
  // start: {penalised: 2.5}
  const Experiment late = Experiment::parse(exptest::tinyExperiment(3) + "start: {penalised: 2.5}\n", "tiny.yaml");
  EXPECT_EQ(playTick(late), 250);
  EXPECT_DOUBLE_EQ(trialScenario(late, t4).game.timeline[0].t_s, 2.5);
}

// The found rule: within `distance` of the ball, seen in the latest
// `seen_frames` frames in a row (the thesis's controller: 5).
TEST(ExperimentFile, FoundRuleCountsFramesInARow) {
  FoundSpec f;
  f.seen_frames = 5;
  const int64_t last = 100;
  EXPECT_FALSE(foundBy(f, last, 0.25, 4, last, 0));  // 4 frames: not yet
  EXPECT_TRUE(foundBy(f, last, 0.25, 5, last, 0));   // 5: found
  EXPECT_TRUE(foundBy(f, last, 0.300, 5, last, 0));  // inclusive
  EXPECT_FALSE(foundBy(f, last, 0.301, 9, last, 0));  // too far
  EXPECT_FALSE(foundBy(f, last - 1, 0.25, 9, last, 0));  // not in the latest frame
  f.seen_frames = 1;
  EXPECT_TRUE(foundBy(f, last, 0.25, 1, last, 0));
  f.sees = false;  // true distance only
  EXPECT_TRUE(foundBy(f, -1, 0, 0, last, 0.29));
  EXPECT_FALSE(foundBy(f, last, 0.1, 9, last, 0.31));
  expectError(replaced(kGood, "distance: 0.3", "distance: 0.3, sees: false, seen_frames: 5"),
              "bad.yaml:5: found.seen_frames", "needs sees: true");
  expectError(replaced(kGood, "distance: 0.3", "distance: 0.3, seen_frames: 0"), "bad.yaml:5: found.seen_frames", "");
}
