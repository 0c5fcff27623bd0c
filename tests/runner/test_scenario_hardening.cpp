// Scenario files: nonsense refused before the first tick, with file, line
// and key (the list: overlapping robots, off-carpet or in-post
// placement, absurd theta, walk speeds, durations and seeds, directories).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "sim/runner/Scenario.hpp"
#include "tests/runner/RunnerTestUtil.hpp"
#include "tests/support/ConfigErrors.hpp"

using simswift::ConfigError;
using simswift::FieldConfig;
using simswift::runner::Scenario;

namespace {

using runnertest::kOneRobot;

std::string fieldCheckedError(const std::string& yaml) {
  return simswift::testing::configError(
      [&] { Scenario::parse(yaml, "s.yaml").checkAgainstField(FieldConfig::spl2017()); });
}

void expectRefused(const std::string& yaml, const std::string& prefix) {
  const std::string err = fieldCheckedError(yaml);
  EXPECT_EQ(err.rfind(prefix, 0), 0u) << yaml << "\n -> " << err;
}

}  // namespace

TEST(ScenarioHardening, OverlappingRobotsAreRefused) {
  expectRefused("robots:\n  - {team: 0, player: 1, x: 1, y: 1}\n  - {team: 1, player: 1, x: 1, y: 1}\n",
                "s.yaml:3: robots[1]: overlaps robots[0]");
  expectRefused("robots:\n  - {team: 0, player: 1, x: 1, y: 1}\n  - {team: 1, player: 1, x: 1.2, y: 1}\n",
                "s.yaml:3: robots[1]: overlaps robots[0]");
  EXPECT_EQ(fieldCheckedError("robots:\n  - {team: 0, player: 1, x: 1, y: 1}\n  - {team: 1, player: 1, x: 1.4, y: 1}\n"), "");
}

TEST(ScenarioHardening, OffCarpetAndInsidePostAreRefused) {
  expectRefused("robots:\n  - {team: 0, player: 1, x: 5.3, y: 0}\n", "s.yaml:2: robots[0] at (5.3");
  expectRefused("robots:\n  - {team: 0, player: 1, x: 49, y: 0}\n", "s.yaml:2: robots[0]");
  expectRefused("robots:\n  - {team: 0, player: 1, x: 4.5, y: -0.8}\n", "s.yaml:2: robots[0]");
  EXPECT_NE(fieldCheckedError("robots:\n  - {team: 0, player: 1, x: 4.5, y: -0.8}\n").find("goal post"), std::string::npos);
  expectRefused(std::string("ball: {x: -4.5, y: 0.8}\n") + kOneRobot, "s.yaml:1: ball");
  expectRefused(std::string("ball: {x: 0, y: 3.8}\n") + kOneRobot, "s.yaml:1: ball");
  expectRefused("robots:\n  - {team: 0, player: 1, x: 1e308, y: 0}\n", "s.yaml:2: robots[0].x:");
}

TEST(ScenarioHardening, ThetaSpeedsAndPushesInRange) {
  expectRefused("robots:\n  - {team: 0, player: 1, theta: 1e30}\n", "s.yaml:2: robots[0].theta:");
  expectRefused("robots:\n  - team: 0\n    player: 1\n    actions:\n      - {t: 1, action: walk, forward: 1e9}\n",
                "s.yaml:5: robots[0].actions[0].forward:");
  expectRefused("robots:\n  - team: 0\n    player: 1\n    actions:\n      - {t: 1, action: walk, turn: 5}\n",
                "s.yaml:5: robots[0].actions[0].turn:");
  expectRefused("robots:\n  - team: 0\n    player: 1\n    actions:\n      - {t: 1, push: {x: 1e150}}\n",
                "s.yaml:5: robots[0].actions[0].push.x:");
}

TEST(ScenarioHardening, DurationsMustRunAtLeastOneTickAndEnd) {
  for (const char* d : {"0.001", ".inf", "9e16", "1e12", "0", "-1", ".nan"})
    expectRefused(std::string("duration: ") + d + "\n" + kOneRobot, "s.yaml:1: duration:");
  EXPECT_EQ(fieldCheckedError(std::string("duration: 0.01\n") + kOneRobot), "");
}

// The seed is read as text by the one seed reader (common/config/Seed.hpp):
// every 64-bit value exactly, never through a double.
TEST(ScenarioHardening, SeedsAreWholeSixtyFourBitNumbersReadExactly) {
  for (const char* s : {"1.5", "1e30", "1e3", "18446744073709551616", "-1", "+1", "0x10", "x", "[1]", "~"})
    expectRefused(std::string("seed: ") + s + "\n" + kOneRobot,
                  "s.yaml:1: seed: must be a whole number in [0, 18446744073709551615]");
  EXPECT_EQ(Scenario::parse(std::string("seed: 18446744073709551615\n") + kOneRobot, "s.yaml").seed, UINT64_MAX);
  // 2^53 + 1: a YAML number (a double) would have read 2^53.
  EXPECT_EQ(Scenario::parse(std::string("seed: 9007199254740993\n") + kOneRobot, "s.yaml").seed,
            9007199254740993ull);
  EXPECT_EQ(Scenario::parse(kOneRobot, "s.yaml").seed, Scenario{}.seed);  // absent: the default
}

TEST(ScenarioHardening, DirectoryIsNotAScenario) {
  try {
    Scenario::loadFile(SIMSWIFT_SOURCE_DIR "/scenarios");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("scenarios:1: is a directory"), std::string::npos) << e.what();
  }
}

TEST(ScenarioHardening, WatchdogOff) {
  EXPECT_EQ(Scenario::parse(std::string("watchdog: off\n") + kOneRobot, "s.yaml").watchdog_s, 0.0);
  expectRefused(std::string("watchdog: 0\n") + kOneRobot, "s.yaml:1: watchdog:");
}

TEST(ScenarioHardening, RelativePathsResolveAgainstTheScenarioFolderThenTheDataFolder) {
  // The shipped scenario names no model: the data folder (build tree's
  // staged copy here) provides it, not the source tree.
  const Scenario sc = Scenario::loadFile(SIMSWIFT_SOURCE_DIR "/scenarios/stand_one.yaml");
  EXPECT_EQ(sc.modelFile().find(SIMSWIFT_SOURCE_DIR "/models"), std::string::npos) << sc.modelFile();
  EXPECT_NE(sc.modelFile().find("share/simswift/models/nao_v5.urdf"), std::string::npos) << sc.modelFile();
  // A model beside the scenario wins.
  const Scenario here = Scenario::parse(std::string("model: stand_one.yaml\n") + kOneRobot,
                                        SIMSWIFT_SOURCE_DIR "/scenarios/x.yaml");
  EXPECT_EQ(here.modelFile(), SIMSWIFT_SOURCE_DIR "/scenarios/stand_one.yaml");
  const Scenario missing = Scenario::parse(std::string("\nmodel: nope.urdf\n") + kOneRobot, "/tmp/x.yaml");
  try {
    missing.modelFile();
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/tmp/x.yaml:2: model: 'nope.urdf' not found", 0), 0u) << e.what();
  }
}

TEST(ScenarioHardening, OversizeAndBinaryFilesAreRefusedWithTheirLine) {
  // Refused from the file's size, before it is read or parsed.
  const std::string path = ::testing::TempDir() + "simswift_test_big_scenario.yaml";
  {
    std::ofstream out(path);
    out << kOneRobot << std::string(300 * 1024, '#') << "\n";
  }
  const std::string err = simswift::testing::configError([&] { Scenario::loadFile(path); });
  EXPECT_EQ(err.rfind(path + ":1: ", 0), 0u) << err;
  EXPECT_NE(err.find("bytes is more than a configuration file can be (256 KB)"), std::string::npos) << err;
  std::remove(path.c_str());

  std::string text = std::string(kOneRobot) + "duration: 5\n";
  text.insert(text.find("duration"), std::string("x\0", 2));  // line 3
  expectRefused(text, "s.yaml:3: contains a NUL byte");
}

// A misspelt key is named at its own line with the key it resembles (issue
// 34 item 5): a robot's required team (it was "missing" at the robot's first
// line), a required key of a timed action, and an optional key.
TEST(ScenarioHardening, MisspeltKeysAreNamedAtTheirLineWithTheNearestKey) {
  EXPECT_EQ(fieldCheckedError("robots:\n  - player: 1\n    taem: 0\n"),
            "s.yaml:3: unknown key 'taem' in robots[0] (did you mean team? a required key, missing)");
  EXPECT_EQ(fieldCheckedError("robots:\n  - team: 0\n    player: 1\n    actions:\n      - {time: 1, action: stand}\n"
                    "      - {t: 2, action: stand}\n"),
            "s.yaml:5: robots[0].actions[0].t: missing required key");  // 1 letter: no guess
  const std::string opt = fieldCheckedError("duraton: 5\nrobots:\n  - {team: 0, player: 1}\n");
  EXPECT_EQ(opt.rfind("s.yaml:1: unknown key 'duraton' in <document> (did you mean duration?); expected one of ", 0), 0u)
      << opt;
}
