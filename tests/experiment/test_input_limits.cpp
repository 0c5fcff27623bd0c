// Experiment files and the inputs they name under the input limits: a sweep
// whose checks would read too many nodes is refused at its sweep: key; each
// cell starts from the file's own settings (the cells share one parse);
// oversize and binary files are refused naming file and line; the shipped
// inputs (model, field, scenarios, experiments) all still load.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "app/experiment/Experiment.hpp"
#include "app/experiment/Sweep.hpp"
#include "sim/nao_model/RobotModel.hpp"
#include "sim/runner/Scenario.hpp"
#include "sim/world/FieldConfig.hpp"
#include "tests/experiment/ExperimentTestUtil.hpp"
#include "tests/support/ConfigErrors.hpp"

using namespace simswift;
using namespace simswift::experiment;

namespace {

namespace fs = std::filesystem;

using exptest::experimentError;

// tinyExperiment(1) has 15 lines; `setups` more setups like its walker
// follow (one line each), then the sweep with `values` delay values.
std::string manySetups(int setups, int values) {
  std::string s = exptest::tinyExperiment(1);
  for (int k = 0; k < setups; ++k)
    s += "  - {name: w" + std::to_string(k) +
         ", behaviour: script, robots: [{team: 19, player: 2, x: -0.5, y: 0.0, theta: 0.0, "
         "actions: [{t: 0.3, action: walk, forward: 250}]}]}\n";
  s += "sweep:\n  team_comms.delay_ms: [0";
  for (int v = 1; v < values; ++v) s += ", " + std::to_string(v);
  return s + "]\n";
}

}  // namespace

TEST(InputLimits, ASweepReadingTooManyNodesIsRefusedAtItsKey) {
  // 1,000 values, each checked on a file of ~680 nodes: over the budget.
  const std::string msg = experimentError(manySetups(20, 1000));
  EXPECT_EQ(msg.rfind("bad.yaml:36: sweep: 1000 checks (each value) of a file of ", 0), 0u) << msg;
  EXPECT_NE(msg.find("is more than " + std::to_string(kMaxSweepNodes) + " nodes to read"), std::string::npos) << msg;

  // 200 values on the same file: read, one checked experiment per cell.
  const Experiment e = Experiment::parse(manySetups(20, 200), "ok.yaml");
  ASSERT_EQ(e.numCells(), 200);
  EXPECT_EQ(e.cell(199).setups.size(), 21u);
  EXPECT_DOUBLE_EQ(e.cell(199).base.team_comms.delay_ms, 199);
  EXPECT_EQ(e.text, manySetups(20, 200));
}

TEST(InputLimits, MoreThanSixteenSweepPathsAreRefusedAtTheSeventeenth) {
  // A cell sets every path: 3,000 one-value paths took 65 s.
  std::string text = exptest::tinyExperiment(1) + "sweep:\n";  // line 16
  for (int k = 0; k < 17; ++k) text += "  setups.walker.config.k" + std::to_string(k) + ": [1]\n";
  const std::string msg = experimentError(text);
  EXPECT_EQ(msg.rfind("bad.yaml:33: sweep: more than 16 paths", 0), 0u) << msg;
  // Sixteen are read (each path checked alone, then the one cell).
  text.erase(text.rfind("  setups.walker.config.k16"));
  const Experiment e = Experiment::parse(text, "ok.yaml");
  EXPECT_EQ(e.sweep.size(), 16u);
  EXPECT_EQ(e.numCells(), 1);
  const std::string& config = e.cell(0).setups[0].robots[0].config_yaml;
  EXPECT_NE(config.find("k0: 1"), std::string::npos) << config;
  EXPECT_NE(config.find("k15: 1"), std::string::npos) << config;
  EXPECT_EQ(e.setups[0].robots[0].config_yaml, "");  // the file's own setup is untouched
}

TEST(InputLimits, EachCellStartsFromTheFilesOwnSettings) {
  // game empty and team_comms absent in the file: a swept value creates
  // them in its check only; the file's own experiment keeps the defaults.
  // (The game axis first: the team_comms values alone come after it.)
  const std::string text = exptest::tinyExperiment(1) +
                           "game:\n"
                           "sweep:\n"
                           "  game.half_duration: [300, 400]\n"
                           "  team_comms.loss: [0.25, 0.75]\n";
  const Experiment e = Experiment::parse(text, "t.yaml");
  ASSERT_EQ(e.numCells(), 4);
  for (int c = 0; c < 4; ++c) {
    EXPECT_DOUBLE_EQ(e.cell(c).base.game.half_duration_s, c < 2 ? 300 : 400) << c;
    EXPECT_DOUBLE_EQ(e.cell(c).base.team_comms.loss, c % 2 ? 0.75 : 0.25) << c;
  }
  // A value alone has the other axis's setting from the file.
  const network::TeamNetworkConfig defaults;
  ASSERT_EQ(e.sweep.size(), 2u);
  EXPECT_DOUBLE_EQ(e.sweep[0].values[1].alone->base.game.half_duration_s, 400);
  EXPECT_DOUBLE_EQ(e.sweep[0].values[1].alone->base.team_comms.loss, defaults.loss);
  EXPECT_DOUBLE_EQ(e.sweep[1].values[0].alone->base.game.half_duration_s, e.base.game.half_duration_s);
  EXPECT_DOUBLE_EQ(e.sweep[1].values[0].alone->base.team_comms.loss, 0.25);
  EXPECT_DOUBLE_EQ(e.base.team_comms.loss, defaults.loss);
  EXPECT_NE(e.base.game.half_duration_s, 300);
  EXPECT_NE(e.base.game.half_duration_s, 400);
}

TEST(InputLimits, OversizeAndBinaryExperimentFilesAreRefusedWithTheirLine) {
  const fs::path path = fs::temp_directory_path() / "simswift_test_big_experiment.yaml";
  {
    std::ofstream out(path);
    out << exptest::tinyExperiment(1) << std::string(300 * 1024, '#') << "\n";
  }
  std::string msg = simswift::testing::configError([&] { Experiment::loadFile(path.string()); });
  EXPECT_EQ(msg.rfind(path.string() + ":1: ", 0), 0u) << msg;
  EXPECT_NE(msg.find("bytes is more than a configuration file can be (256 KB)"), std::string::npos) << msg;
  fs::remove(path);

  std::string text = exptest::tinyExperiment(1);
  text.insert(text.find("balls:"), std::string("# \0\n", 4));  // line 7
  msg = experimentError(text);
  EXPECT_EQ(msg.rfind("bad.yaml:7: ", 0), 0u) << msg;
  EXPECT_NE(msg.find("NUL byte"), std::string::npos) << msg;

  msg = simswift::testing::configError([&] { Experiment::loadFile(SIMSWIFT_SOURCE_DIR "/scenarios"); });
  EXPECT_NE(msg.find("/scenarios:1: is a directory"), std::string::npos) << msg;
}

// setups x positions x trials_per_position counted in 64 bits (issue 34
// item 3): 250 x 1000 x 10000 = 2.5e9 wrapped to a negative int and passed
// the 10^6 check; 250 x 1000 x 4 = 10^6 exactly is the largest accepted.
TEST(InputLimits, TrialCountsBeyondAnIntAreRefusedAtTheirKey) {
  auto file = [](int trials) {
    std::ostringstream s;
    s << "name: huge\nseed: 1\ntime_limit: 10\ntrials_per_position: " << trials << "\nballs:\n";  // line 4
    for (int k = 0; k < 1000; ++k)  // a 40 x 25 grid, 0.2 m apart (m, field frame)
      s << "  - {position: " << k + 1 << ", x: " << -4.0 + 0.2 * (k % 40) << ", y: " << -2.5 + 0.2 * (k / 40) << "}\n";
    s << "setups:\n";
    for (int k = 0; k < 250; ++k)  // the robot beyond the grid's last row (y = 2.3 m)
      s << "  - {name: s" << k << ", behaviour: script, robots: [{team: 19, player: 2, x: 0, y: 3.2, theta: 0, "
        << "actions: [{t: 0, action: stand}]}]}\n";
    return s.str();
  };
  const std::string msg = experimentError(file(10000));
  EXPECT_EQ(msg, "bad.yaml:4: trials_per_position: 250 setups x 1000 positions x 10000 = 2500000000 trials is more "
                 "than 1000000") << msg;
  const Experiment e = Experiment::parse(file(4), "ok.yaml");
  EXPECT_EQ(e.numTrials(), 1000000);
  EXPECT_EQ(e.countTrials(), kMaxTrials);
}

TEST(InputLimits, ShippedInputsStillLoad) {
  const fs::path src = SIMSWIFT_SOURCE_DIR;
  EXPECT_NO_THROW(RobotModel::loadUrdf((src / "models" / "nao_v5.urdf").string()));
  int experiments = 0, scenarios = 0;
  for (const auto& f : fs::directory_iterator(src / "fields")) EXPECT_NO_THROW(FieldConfig::loadYaml(f.path().string()));
  for (const auto& f : fs::directory_iterator(src / "scenarios")) {
    if (f.is_directory()) continue;  // scenarios/tests: test files (tests/app's ShippedScenarios)
    std::ifstream in(f.path());
    std::stringstream s;
    s << in.rdbuf();
    // An experiment names itself; a scenario does not.
    const bool experiment = s.str().rfind("name:", 0) == 0 || s.str().find("\nname:") != std::string::npos;
    const std::string msg = simswift::testing::configError([&] {
      if (experiment)
        Experiment::loadFile(f.path().string());
      else
        runner::Scenario::loadFile(f.path().string());
    });
    EXPECT_EQ(msg, "") << f.path();
    (experiment ? experiments : scenarios) += 1;
  }
  EXPECT_GE(experiments, 4);
  EXPECT_GE(scenarios, 8);
}

// The experiment's seed is read by the one seed reader: every 64-bit value
// exactly (a YAML number is exact only up to 2^53), anything else refused at
// seed: with the range.
TEST(InputLimits, TheExperimentSeedTakesAll64BitsAndNothingElse) {
  auto withSeed = [](const std::string& seed) {
    std::string t = exptest::tinyExperiment(1);
    return t.replace(t.find("seed: 11"), 8, "seed: " + seed);
  };
  EXPECT_EQ(Experiment::parse(withSeed("18446744073709551615"), "ok.yaml").seed, 18446744073709551615ull);
  EXPECT_EQ(Experiment::parse(withSeed("9007199254740993"), "ok.yaml").seed, 9007199254740993ull);  // 2^53 + 1
  for (const char* bad : {"1.5", "-1", "18446744073709551616", "1e3"}) {
    const std::string err = experimentError(withSeed(bad));
    EXPECT_NE(err.find("bad.yaml:2: seed: must be a whole number in [0, 18446744073709551615]"), std::string::npos)
        << bad << ": " << err;
  }
  std::string none = exptest::tinyExperiment(1);
  none.erase(none.find("seed: 11\n"), 9);
  EXPECT_NE(experimentError(none).find("seed: missing required key"), std::string::npos) << experimentError(none);
}
