// A key that is not a name -- a list, a map or null, YAML's "? [never]: ..."
// -- in any file a user gives: exit 2 and "file:line: key path: a key must be
// a name", never yaml-cpp's unplaced "bad conversion" (issue 45, item 6).
// One case per reader: the scenario (a robot, a launched program's env:, a
// robot's actions:), the field, the test file (a pass: operator), the
// experiment (a ball, a setup's and a robot's config:, the sweep) and the
// robot program's config file (simswift-agent --config).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "tests/support/Shell.hpp"

namespace {

namespace fs = std::filesystem;
using simswift::testing::shell;
using simswift::testing::writeText;

std::string writeInput(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("simswift_bad_keys_" + std::to_string(getpid()));
  fs::create_directories(dir);
  writeText((dir / name).string(), text);
  return (dir / name).string();
}

void expectBadKey(const std::string& command, const std::string& where) {
  const auto r = shell(std::string(SIMSWIFT_BINARY_DIR) + "/" + command);
  EXPECT_EQ(r.code, 2) << command << "\n" << r.output;
  EXPECT_NE(r.output.find(where + ": a key must be a name, not "), std::string::npos)
      << command << "\nexpected: " << where << "\n" << r.output;
  EXPECT_EQ(r.output.find("bad conversion"), std::string::npos) << r.output;
}

const std::string kRobot = "  - {team: 19, player: 2, x: -1.0, y: 0.0, theta: 0.0}\n";

}  // namespace

TEST(BadKeys, ScenarioFieldAndRobotConfigExitTwoAtTheKey) {
  std::string s = writeInput("robot.yaml", "duration: 0.1\nrobots:\n  - {team: 19, ? [player]: 2, x: -1.0}\n");
  expectBadKey("simswift run " + s + " --quiet", s + ":3: robots[0]");
  s = writeInput("env.yaml", "duration: 0.1\nrobots:\n  - {team: 19, player: 2, x: -1.0, y: 0.0,\n"
                        "     program: {command: [/bin/true], env: {A: b, ? {c: d}: e}}}\n");
  expectBadKey("simswift run " + s + " --quiet", s + ":4: robots[0].program.env");
  s = writeInput("actions.yaml", "duration: 0.1\nrobots:\n  - team: 19\n    player: 2\n"
                            "    actions: [{t: 0, ? ~ : stand}]\n");
  expectBadKey("simswift run " + s + " --quiet", s + ":5: robots[0].actions[0]");
  const std::string f = writeInput("field_key.yaml", "field:\n  goal: {? [post_height]: 0.5}\n");
  s = writeInput("with_field.yaml", "field: field_key.yaml\nduration: 0.1\nrobots:\n" + kRobot);
  expectBadKey("simswift run " + s + " --quiet", f + ":2: field.goal");
  // The robot program's own config file: read before it attaches anywhere.
  const std::string c = writeInput("setup.yaml", "team: 19\nplayer: 2\nstart: {x: 0, y: 0, ? [theta]: 1}\n");
  expectBadKey("simswift-agent --config " + c, c + ":3: start");
}

TEST(BadKeys, TestFileExitsTwoAtTheKey) {
  // The file: a list as a pass: operator.
  const std::string t = writeInput("t.yaml",
                              "name: t\nseed: 3\ntests:\n  - name: walk\n"
                              "    scenario: {robots: [{team: 19, player: 2, x: -1.0, y: 0.0}]}\n"
                              "    pass: {? [never]: {fallen: any}}\n");
  expectBadKey("simswift test " + t + " --check", t + ":6: tests[0].pass");
  const std::string u = writeInput("u.yaml",
                              "name: t\nseed: 3\ntests:\n  - name: walk\n"
                              "    scenario: {robots: [{team: 19, player: 2, x: -1.0, y: 0.0}]}\n"
                              "    pass: {never: {? {fallen: any}: 1}}\n");
  expectBadKey("simswift test " + u + " --check", u + ":6: tests[0].pass.never");
}

TEST(BadKeys, ExperimentExitsTwoAtTheKey) {
  const auto experiment = [](const std::string& balls, const std::string& setup, const std::string& robot,
                             const std::string& tail) {
    return "name: e\nseed: 1\ntime_limit: 10\ntrials_per_position: 1\nfound: {distance: 0.3}\n"  // 1-5
           "balls:\n  - {position: 1, x: 1.0, " + balls + "}\n"                                  // 6-7
           "setups:\n  - name: a\n    behaviour: findball2017\n" + setup +                      // 8-10 (11: a setup config)
           "    robots:\n      - {team: 19, player: 2, x: -1.0, y: 0.0, theta: 0.0" + robot + "}\n" + tail;
  };
  std::string e = writeInput("e1.yaml", experiment("? [y]: 0.0", "", "", ""));
  expectBadKey("simswift experiment " + e + " --check", e + ":7: balls[0]");
  e = writeInput("e2.yaml", experiment("y: 0.0", "    config: {? [search]: 1}\n", "", ""));
  expectBadKey("simswift experiment " + e + " --check", e + ":11: setups[0].config");
  e = writeInput("e3.yaml", experiment("y: 0.0", "", ", config: {? [search]: 1}", ""));
  expectBadKey("simswift experiment " + e + " --check", e + ":12: setups[0].robots[0].config");
  e = writeInput("e4.yaml", experiment("y: 0.0", "", "", "sweep: {? [team_comms]: [0, 1]}\n"));
  expectBadKey("simswift experiment " + e + " --check", e + ":13: sweep");
}
