// runExperiment's errors for a bad experiment file carry the file, line and
// key as their throw site in app/experiment set them (the API reads nothing
// back out of the message): the file's shape, a sweep path, a swept value.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "simswift/Experiment.hpp"

namespace {

// 15 lines: `sweep:` below it is line 16, its first path line 17.
const std::string kTiny =
    "name: tiny\n"
    "seed: 11\n"
    "time_limit: 7\n"
    "trials_per_position: 1\n"
    "found: {distance: 0.3, sees: true}\n"
    "tracks: {every: 0.5}\n"
    "balls:\n"
    "  - {position: 1, x: 0.7, y: 0.0}\n"
    "  - {position: 2, x: 0.0, y: 1.5}\n"
    "setups:\n"
    "  - name: walker\n"
    "    behaviour: script\n"
    "    robots:\n"
    "      - {team: 19, player: 2, x: -0.5, y: 0.0, theta: 0.0,\n"
    "         actions: [{t: 0.3, action: walk, forward: 250}]}\n";

struct Refusal {
  std::string file, key, what;
  int line = 0;
};

// The ConfigError runExperiment throws for `text` as a file.
Refusal refusal(const std::string& text) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("simswift_api_experr_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "bad.yaml").string();
  std::ofstream(path) << text;
  Refusal r;
  try {
    simswift::api::ExperimentOptions o;
    o.out_dir = (dir / "out").string();
    simswift::api::runExperiment(path, o);
    r.what = "accepted";
  } catch (const simswift::api::ConfigError& e) {
    EXPECT_EQ(e.file, path);
    r = {e.file, e.key, e.what(), e.line};
    // The message begins with the parts it carries.
    EXPECT_EQ(r.what.rfind(path + ":" + std::to_string(e.line) + ": " + (e.key.empty() ? "" : e.key)), 0u) << r.what;
  }
  std::filesystem::remove_all(dir);
  return r;
}

}  // namespace

TEST(ExperimentErrors, AFileThatIsNoMapNamesItsFirstLine) {
  const Refusal r = refusal("- 1\n- 2\n");
  EXPECT_EQ(r.line, 1) << r.what;
  EXPECT_EQ(r.key, "") << r.what;
  EXPECT_NE(r.what.find("an experiment file is a map"), std::string::npos) << r.what;
}

TEST(ExperimentErrors, ASweepPathNamesItsLineAndKey) {
  const Refusal r = refusal(kTiny + "sweep:\n  team_comms.loss: 0.1\n");
  EXPECT_EQ(r.line, 17) << r.what;
  EXPECT_EQ(r.key, "sweep.team_comms.loss") << r.what;
  EXPECT_NE(r.what.find("must be a list"), std::string::npos) << r.what;
}

TEST(ExperimentErrors, ASweptValueNamesItsOwnLineAndIndex) {
  const Refusal r = refusal(kTiny + "sweep:\n  team_comms.loss:\n    - 0\n    - 2\n");
  EXPECT_EQ(r.line, 19) << r.what;
  EXPECT_EQ(r.key, "sweep.team_comms.loss[1]") << r.what;  // the path alone; the message shows the value
  EXPECT_NE(r.what.find("sweep.team_comms.loss[1] = 2: team_comms.loss: must be in [0, 1]"), std::string::npos)
      << r.what;
}

TEST(ExperimentErrors, ACellOfValuesFineAloneNamesTheSweep) {
  const Refusal r = refusal(kTiny +
                            "vision: {ball: {max_distance_mm: 5000}}\n"
                            "sweep:\n"
                            "  vision.ball.min_distance_mm: [0, 3000]\n"
                            "  vision.ball.max_distance_mm: [2500, 5000]\n");
  EXPECT_EQ(r.line, 17) << r.what;
  EXPECT_EQ(r.key, "sweep") << r.what;
  EXPECT_NE(r.what.find("sweep: cell 2 ("), std::string::npos) << r.what;
}

// A behaviour override the behaviour's reader refuses (checked before any
// trial) names the file, the line and the key of the behaviour it overrides:
// the robot's own, else its setup's; the message says which override.
TEST(ExperimentErrors, ABadBehaviourOverrideNamesItsBehavioursLineAndKey) {
  const std::string head =
      "name: tiny\n"                              // 1
      "seed: 11\n"                                // 2
      "time_limit: 7\n"                           // 3
      "trials_per_position: 1\n"                  // 4
      "found: {distance: 0.3, sees: true}\n"      // 5
      "balls:\n"                                  // 6
      "  - {position: 1, x: 0.7, y: 0.0}\n"       // 7
      "setups:\n"                                 // 8
      "  - name: searcher\n"                      // 9
      "    behaviour: findball2017\n"             // 10
      "    robots:\n";                            // 11
  const Refusal setups = refusal(head +
                                 "      - {team: 19, player: 2, x: -0.5, y: 0.0, theta: 0.0,\n"  // 12
                                 "         config: {search: {spin_fast: on}}}\n");               // 13
  EXPECT_EQ(setups.line, 10) << setups.what;
  EXPECT_EQ(setups.key, "setups[0].behaviour") << setups.what;
  EXPECT_NE(setups.what.find("unknown key 'spin_fast'"), std::string::npos) << setups.what;
  const Refusal own = refusal(head +
                              "      - {team: 19, player: 2, x: -0.5, y: 0.0, theta: 0.0}\n"      // 12
                              "      - {team: 19, player: 3, x: -0.5, y: 1.0, theta: 0.0,\n"      // 13
                              "         behaviour: findball2016, config: {search2016: {pass_distance: 1}}}\n");  // 14
  EXPECT_EQ(own.line, 14) << own.what;
  EXPECT_EQ(own.key, "setups[0].robots[1].behaviour") << own.what;
  EXPECT_NE(own.what.find("search2016.pass_distance: must be in [10, 5000]"), std::string::npos) << own.what;
}
