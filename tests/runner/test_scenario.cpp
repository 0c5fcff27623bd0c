// Scenario loading: defaults, and errors that name the file, line and key.
#include <gtest/gtest.h>

#include "sim/runner/Scenario.hpp"
#include "tests/support/ConfigErrors.hpp"

using simswift::ConfigError;
using simswift::runner::RobotSpec;
using simswift::runner::Scenario;

namespace {
std::string errorOf(const std::string& yaml) {
  return simswift::testing::configError([&] { Scenario::parse(yaml, "scenario.yaml"); });
}
}  // namespace

TEST(Scenario, ReadsRobotsBallAndSwitches) {
  const Scenario s = Scenario::parse(
      "duration: 3.5\n"
      "seed: 42\n"
      "noise: {gyro: off}\n"
      "physics: {substeps: 4, solver: quick}\n"
      "ball: {x: 1.0, y: -0.5}\n"
      "robots:\n"
      "  - {team: 1, player: 3, x: 2.0, y: 1.0, theta: 3.1, posture: crouch, program: external}\n"
      "  - team: 0\n"
      "    player: 1\n"
      "    script:\n"
      "      - {t: 1.0, joint: HeadYaw, angle: 0.5, duration: 0.25}\n"
      "      - {t: 2.0, posture: limp}\n",
      "scenario.yaml");
  EXPECT_DOUBLE_EQ(s.duration, 3.5);
  EXPECT_EQ(s.seed, 42u);
  EXPECT_TRUE(s.noise.on);
  EXPECT_FALSE(s.noise.gyro);
  EXPECT_TRUE(s.noise.accel);
  EXPECT_EQ(s.world.substeps, 4);
  EXPECT_EQ(s.world.solver, simswift::WorldConfig::Solver::Quick);
  ASSERT_TRUE(s.ball.has_value());
  EXPECT_DOUBLE_EQ(s.ball->second, -0.5);
  ASSERT_EQ(s.robots.size(), 2u);
  EXPECT_EQ(s.robots[0].team, 1);
  EXPECT_EQ(s.robots[0].posture, agent::program::Posture::Crouch);
  EXPECT_EQ(s.robots[0].program, RobotSpec::Program::External);
  EXPECT_EQ(s.robots[1].posture, agent::program::Posture::Stand);  // default
  ASSERT_EQ(s.robots[1].setup.script.size(), 2u);
  EXPECT_EQ(s.robots[1].setup.script[0].joint, 0);  // HeadYaw
  EXPECT_DOUBLE_EQ(s.robots[1].setup.script[0].duration_s, 0.25);
  EXPECT_EQ(s.robots[1].setup.script[1].posture, agent::program::Posture::Limp);
  // Default model and field: found (scenario folder, then the data folder).
  EXPECT_NE(s.modelFile().find("models/nao_v5.urdf"), std::string::npos) << s.modelFile();
  EXPECT_NE(s.fieldFile().find("fields/spl_2017.yaml"), std::string::npos) << s.fieldFile();
}

TEST(Scenario, BadTeamNamesTheLineAndKey) {
  const std::string m = errorOf(
      "duration: 2\n"
      "robots:\n"
      "  - {team: 0, player: 1}\n"
      "  - team: 300\n"
      "    player: 2\n");
  EXPECT_NE(m.find("scenario.yaml:4: robots[1].team:"), std::string::npos) << m;
  EXPECT_NE(m.find("got 300"), std::string::npos) << m;
}

TEST(Scenario, UnknownKeysAreErrors) {
  const std::string top = errorOf("duration: 2\nduraton: 3\nrobots:\n  - {team: 0, player: 1}\n");
  EXPECT_NE(top.find("scenario.yaml:2"), std::string::npos) << top;
  EXPECT_NE(top.find("duraton"), std::string::npos) << top;
  const std::string robot = errorOf("robots:\n  - {team: 0, player: 1, postur: stand}\n");
  EXPECT_NE(robot.find("scenario.yaml:2: unknown key 'postur' in robots[0]"), std::string::npos) << robot;
}

TEST(Scenario, OtherBadValuesSayWhatIsWrong) {
  EXPECT_NE(errorOf("robots:\n  - {team: 0, player: 1, posture: sit}\n").find("robots[0].posture"),
            std::string::npos);
  EXPECT_NE(errorOf("robots:\n  - {team: 0, player: 1}\n  - {team: 0, player: 1}\n").find("appears twice"),
            std::string::npos);
  const std::string joint =
      errorOf("robots:\n  - team: 0\n    player: 1\n    script:\n      - {t: 1, joint: Elbow, angle: 1}\n");
  EXPECT_NE(joint.find("scenario.yaml:5: robots[0].script[0].joint: unknown joint 'Elbow'"), std::string::npos)
      << joint;
  EXPECT_NE(errorOf("duration: -1\nrobots:\n  - {team: 0, player: 1}\n").find("scenario.yaml:1: duration"),
            std::string::npos);
  EXPECT_NE(errorOf("duration: 1\n").find("at least one robot"), std::string::npos);
  EXPECT_NE(errorOf("robots:\n  - {team: 0, player: 1, program: external, script: []}\n").find("builtin"),
            std::string::npos);
  try {
    Scenario::loadFile("/nonexistent/scenario.yaml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scenario.yaml"), std::string::npos);
  }
}

TEST(Scenario, ShippedScenariosLoad) {
  for (const char* f : {"stand_one.yaml", "stand_three.yaml", "stand_ten.yaml", "external_one.yaml"}) {
    const Scenario s = Scenario::loadFile(std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/" + f);
    EXPECT_FALSE(s.robots.empty()) << f;
  }
}

TEST(Scenario, LibagentAndClickValuesAreCheckedWithFileLineAndKey) {
  struct Case {
    const char* robot;
    const char* want;
  };
  const Case cases[] = {
      {"libagent: {release: 2019}", "robots[0].libagent.release: expected one of 2016, 2017, 2018"},
      {"libagent: {start: floppy}", "robots[0].libagent.start: expected one of stiff, limp"},
      {"program: external, actions: [{t: 1, click: elbow}]", "robots[0].actions[0].click: expected one of chest"},
      {"program: external, actions: [{t: 1, click: chest, count: 0}]", "robots[0].actions[0].count"},
      {"libagent: {release: 2016}", "robots[0].libagent: the builtin robot program speaks the 2017 block"},
  };
  for (const Case& c : cases) {
    try {
      Scenario::parse(std::string("duration: 1\nrobots:\n  - {team: 19, player: 1, ") + c.robot + "}\n", "bad.yaml");
      ADD_FAILURE() << c.robot << ": accepted";
    } catch (const simswift::ConfigError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("bad.yaml:3"), std::string::npos) << m;
      EXPECT_NE(m.find(c.want), std::string::npos) << m;
    }
  }
}

// `inertial:` chooses the raw slots' signs (the choice no public source
// settles, docs/libagent.md); only +1 and -1, named at the key's line.
TEST(Scenario, InertialRawSignsAreReadAndCheckedAtTheirLine) {
  const Scenario d = Scenario::parse("robots:\n  - {team: 0, player: 1}\n", "scenario.yaml");
  EXPECT_EQ(d.gyr_raw_sign, 1);
  EXPECT_EQ(d.acc_raw_sign, 1);
  const Scenario s =
      Scenario::parse("inertial: {gyr_raw_sign: -1}\nrobots:\n  - {team: 0, player: 1}\n", "scenario.yaml");
  EXPECT_EQ(s.gyr_raw_sign, -1);
  EXPECT_EQ(s.acc_raw_sign, 1);
  const std::string bad = errorOf("duration: 2\ninertial:\n  acc_raw_sign: 2\nrobots:\n  - {team: 0, player: 1}\n");
  EXPECT_NE(bad.find("scenario.yaml:3: inertial.acc_raw_sign: must be 1 or -1, got 2"), std::string::npos) << bad;
}
