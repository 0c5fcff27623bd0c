// The recording's entry points as a user runs them: `simswift run
// --record`, `simswift test --record failures|all` (a failing run's
// recording named in its report line, report.md and the JUnit failure).
// The messages are uncompressed JSON, so the file's bytes show them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/Shell.hpp"

namespace {

namespace fs = std::filesystem;
using simswift::testing::readText;
using simswift::testing::shell;
using simswift::testing::writeText;

const std::string kBin = std::string(SIMSWIFT_BINARY_DIR) + "/simswift";

std::string freshDir(const std::string& name) {
  const std::string d = std::string(SIMSWIFT_BINARY_DIR) + "/record_tmp/" + name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// One test that passes on every seed, one that never does.
const std::string kTiny =
    "name: tiny\n"
    "seed: 5\n"
    "tests:\n"
    "  - name: stands\n"
    "    seeds: 2\n"
    "    time_limit: 0.3\n"
    "    required: 0.3\n"
    "    scenario: {robots: [{team: 19, player: 2, x: -1.0, y: 0.0, theta: 0.0}]}\n"
    "    pass: {never: {fallen: any}}\n"
    "  - name: never_scores\n"
    "    seeds: 2\n"
    "    time_limit: 0.3\n"
    "    required: 0.3\n"
    "    scenario: {robots: [{team: 19, player: 2, x: -1.0, y: 0.0, theta: 0.0}]}\n"
    "    pass: {within: {seconds: 0.3, that: {ball_in_goal: red}}}\n";

}  // namespace

TEST(RecordCommands, RunRecordWritesTheFileAndNamesIt) {
  const std::string d = freshDir("run");
  const auto r = shell(kBin + " run " + SIMSWIFT_SOURCE_DIR + "/scenarios/walk_one.yaml --duration 0.5 --inline --record " +
                       d + "/w.mcap --record-rate 10");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("recording " + d + "/w.mcap"), std::string::npos) << r.output;
  const std::string b = bytes(d + "/w.mcap");
  EXPECT_EQ(b.substr(0, 5), "\x89MCAP");
  EXPECT_NE(b.find("\"child_frame_id\":\"robot0/torso\""), std::string::npos);
  // A bad rate and a file that cannot be written are refused.
  const auto bad = shell(kBin + " run " + SIMSWIFT_SOURCE_DIR + "/scenarios/walk_one.yaml --record " + d +
                         "/x.mcap --record-rate 0");
  EXPECT_EQ(bad.code, 2) << bad.output;
  const auto nowhere = shell(kBin + " run " + SIMSWIFT_SOURCE_DIR +
                             "/scenarios/walk_one.yaml --duration 0.1 --record /nonexistent-dir/x.mcap");
  EXPECT_EQ(nowhere.code, 1) << nowhere.output;
  EXPECT_NE(nowhere.output.find("recording /nonexistent-dir/x.mcap: cannot open"), std::string::npos) << nowhere.output;
}

TEST(RecordCommands, TestRecordFailuresKeepsAndNamesTheFailingRuns) {
  const std::string d = freshDir("test");
  writeText(d + "/tiny.yaml", kTiny);
  const auto r = shell(kBin + " test " + d + "/tiny.yaml --out " + d + "/out --jobs 2 --record failures --junit " + d +
                       "/junit.xml");
  EXPECT_EQ(r.code, 1) << r.output;  // never_scores fails
  const std::string rec0 = d + "/out/recordings/never_scores_run0.mcap";
  const std::string rec1 = d + "/out/recordings/never_scores_run1.mcap";
  EXPECT_TRUE(fs::exists(rec0) && fs::exists(rec1)) << r.output;
  EXPECT_FALSE(fs::exists(d + "/out/recordings/stands_run0.mcap")) << "a passing run's recording was kept";
  // Named in the run's report line (progress), the console summary,
  // report.md and the JUnit failure.
  EXPECT_NE(r.output.find("never_scores run 0 (seed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(recording " + rec0 + ")"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(at the failure: simswift view " + rec0 + " --at "), std::string::npos) << r.output;  // docs/viewer.md
  EXPECT_NE(readText(d + "/out/report.md").find("(recording " + rec1 + ")"), std::string::npos);
  EXPECT_NE(readText(d + "/junit.xml").find("(recording " + rec1 + ")"), std::string::npos);
  // The recording ends with the verdict, an ERROR naming the condition.
  const std::string b = bytes(rec0);
  EXPECT_NE(b.find("\"level\":4,\"message\":\"never_scores: failed at 0.30 s: "), std::string::npos);
  EXPECT_NE(b.find("\"name\":\"verdict\""), std::string::npos);

  const auto all = shell(kBin + " test " + d + "/tiny.yaml --out " + d + "/all --jobs 2 --record all --progress none");
  EXPECT_EQ(all.code, 1) << all.output;
  EXPECT_TRUE(fs::exists(d + "/all/recordings/stands_run1.mcap")) << all.output;
  EXPECT_NE(bytes(d + "/all/recordings/stands_run1.mcap").find("\"message\":\"stands: passed at 0.30 s\""),
            std::string::npos);
  EXPECT_EQ(shell(kBin + " test " + d + "/tiny.yaml --record sometimes").code, 2);
}

TEST(RecordCommands, ExperimentRecordsTheChosenTrials) {
  const std::string d = freshDir("experiment");
  const auto r = shell(kBin + " experiment " + SIMSWIFT_SOURCE_DIR + "/scenarios/findball_quick.yaml --trial 0 --record 0 --out " +
                       d + "/out");
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string b = bytes(d + "/out/recordings/trial_0.mcap");
  ASSERT_GT(b.size(), 16u) << r.output;
  EXPECT_EQ(b.substr(b.size() - 8), std::string("\x89MCAP0\r\n", 8));  // complete
  // Each robot's belief through the observer hook: its behaviour's activity.
  EXPECT_NE(b.find("\"behaviour\":\"findball2016\""), std::string::npos);
  EXPECT_NE(b.find("robot2: penalised manual"), std::string::npos);
  const auto bad = shell(kBin + " experiment " + SIMSWIFT_SOURCE_DIR + "/scenarios/findball_quick.yaml --record 99 --out " + d +
                         "/bad");
  EXPECT_EQ(bad.code, 2) << bad.output;
}
