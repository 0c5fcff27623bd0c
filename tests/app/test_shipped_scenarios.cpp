// Every file in scenarios/ is loaded as a user would load it, so a shipped
// file can never rot: experiments through `simswift experiment --check`,
// test files (scenarios/tests/) through `simswift test --check`,
// scenarios through `simswift run --check` and, where every robot runs the
// builtin program, a brief run (0.2 simulated s) as well. A scenario whose
// robots run in another process is only checked: its program is not ours
// to start here, and two tests must not share libagent names. A scenario
// that renders is only checked in a build without cameras.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sim/runner/Runner.hpp"
#include "tests/support/Shell.hpp"

namespace {

namespace fs = std::filesystem;

using simswift::testing::ShellResult;
using simswift::testing::shell;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A top-level `balls:` key makes a file an experiment (app/experiment/Experiment.hpp).
bool isExperiment(const std::string& text) { return text.rfind("balls:", 0) == 0 || text.find("\nballs:") != std::string::npos; }

std::vector<fs::path> shippedFiles() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(fs::path(SIMSWIFT_SOURCE_DIR) / "scenarios"))
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

const std::string kBin = std::string(SIMSWIFT_BINARY_DIR) + "/simswift";

TEST(ShippedScenarios, ThereAreSome) { EXPECT_GE(shippedFiles().size(), 10u); }

TEST(ShippedScenarios, EveryFileIsAcceptedAndBuiltinOnesRun) {
  for (const fs::path& f : shippedFiles()) {
    SCOPED_TRACE(f.filename().string());
    const std::string text = slurp(f);
    if (isExperiment(text)) {
      const ShellResult r = shell(kBin + " experiment " + f.string() + " --check");
      EXPECT_EQ(r.code, 0) << r.output;
      continue;
    }
    const ShellResult c = shell(kBin + " run " + f.string() + " --check");
    EXPECT_EQ(c.code, 0) << c.output;
    EXPECT_NE(c.output.find(": ok ("), std::string::npos) << c.output;
    if (text.find("external") != std::string::npos) continue;  // its program runs elsewhere
    // Rendering needs a build with cameras (the sanitizer builds have none).
    if (text.find("\ncamera:") != std::string::npos && !simswift::runner::Runner::camerasAvailable()) continue;
    const ShellResult r = shell(kBin + " run " + f.string() + " --duration 0.2 --quiet");
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("hash "), std::string::npos) << r.output;
  }
}

// Test files (scenarios/tests/, the CI template's example): every test and
// every run's fuzzed start, in both forms. The reference program's short
// form runs in tests/scenario_tests.
TEST(ShippedScenarios, EveryTestFileIsAccepted) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(fs::path(SIMSWIFT_SOURCE_DIR) / "scenarios" / "tests"))
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  files.push_back(fs::path(SIMSWIFT_SOURCE_DIR) / "examples" / "ci" / "team_tests.yaml");
  EXPECT_GE(files.size(), 2u);
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    for (const char* form : {"", " --short"}) {
      const ShellResult r = shell(kBin + " test " + f.string() + " --check" + form);
      EXPECT_EQ(r.code, 0) << r.output;
      EXPECT_NE(r.output.find("valid"), std::string::npos) << r.output;
    }
  }
}

TEST(ShippedScenarios, CheckRefusesABadFileWithExitTwo) {
  const fs::path bad = fs::temp_directory_path() / "simswift_bad_ball.yaml";
  {
    std::ofstream out(bad);
    out << "duration: 1\nball: nowhere\nrobots:\n  - {team: 19, player: 1, x: 0, y: 0, theta: 0}\n";
  }
  const ShellResult r = shell(kBin + " run " + bad.string() + " --check");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(":2"), std::string::npos) << r.output;  // file:line
  EXPECT_NE(r.output.find("ball"), std::string::npos) << r.output;
  fs::remove(bad);
}

}  // namespace
