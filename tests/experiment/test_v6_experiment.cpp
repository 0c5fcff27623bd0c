// The find-ball experiment with NAO V6 robots (a setup whose robots have
// `lola: {}`): the reference program over LoLA at 12 ms finds the ball, a
// V6 setup beside a V5 one in one file, the same results.csv with one or
// two workers (each trial's sockets are its process's own), and a setup
// mixing V5 and V6 robots refused at the robot's line and key.
#include <gtest/gtest.h>
#include <signal.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "app/experiment/Batch.hpp"
#include "app/experiment/Experiment.hpp"
#include "tests/experiment/ExperimentTestUtil.hpp"
#include "tests/support/ConfigErrors.hpp"

using simswift::experiment::Experiment;

namespace {

const std::string kV6 =
    "name: v6\nseed: 2019\ntime_limit: 60\ntrials_per_position: 1\nstart: {penalised: 1.0}\n"
    "found: {distance: 0.300, sees: true, seen_frames: 5}\nnoise: on\n"
    "vision: {ball: {max_distance_mm: 2500}}\n"
    "balls:\n  - {position: 8, x: -3.5, y: 0.0}\n"
    "setups:\n"
    "  - name: v5\n    behaviour: findball2017\n    robots:\n"
    "      - {team: 19, player: 2, x: -3.25, y: 3.0, theta: -1.5708}\n"
    "      - {team: 19, player: 3, x: -2.0, y: -3.0, theta: 1.5708}\n"
    "  - name: v6\n    behaviour: findball2017\n    robots:\n"
    "      - {team: 19, player: 2, x: -3.25, y: 3.0, theta: -1.5708, lola: {}}\n"
    "      - {team: 19, player: 3, x: -2.0, y: -3.0, theta: 1.5708, lola: {}}\n";

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string f;
  std::istringstream in(line);
  while (std::getline(in, f, ',')) out.push_back(f);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

}  // namespace

TEST(V6Experiment, FindsTheBallAndIsTheSameWithOneOrTwoWorkers) {
  const Experiment e = Experiment::parse(kV6, "v6.yaml");
  ASSERT_EQ(e.setups.size(), 2u);
  EXPECT_EQ(simswift::experiment::setupTickUs(e.setups[0]), 10000);
  EXPECT_EQ(simswift::experiment::setupTickUs(e.setups[1]), 12000);
  EXPECT_EQ(simswift::experiment::playTick(e, 12000), 83);  // 1.0 s penalised, in 12 ms ticks
  const std::string one = exptest::freshDir("one"), two = exptest::freshDir("two");
  ASSERT_TRUE(exptest::runInto(e, one, 1).assembled);
  ASSERT_TRUE(exptest::runInto(e, two, 2).assembled);
  const std::string csv = exptest::readAll(one + "/results.csv");
  EXPECT_EQ(csv, exptest::readAll(two + "/results.csv"));
  // trial,setup,position,repeat,seed,found,...: the V6 trial finds the ball.
  std::istringstream in(csv);
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(in, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 3u) << csv;
  EXPECT_EQ(rows[2].rfind("1,v6,8,0,", 0), 0u) << rows[2];
  EXPECT_NE(rows[2].find(",1,"), std::string::npos) << "found: " << rows[2];
}

TEST(V6Experiment, ASetupMixingV5AndV6IsRefused) {
  const std::string mixed =
      kV6.substr(0, kV6.find("  - name: v6")) +
      "  - name: mixed\n    behaviour: findball2017\n    robots:\n"
      "      - {team: 19, player: 2, x: -3.25, y: 3.0, theta: -1.5708}\n"
      "      - {team: 19, player: 3, x: -2.0, y: -3.0, theta: 1.5708, lola: {}}\n";
  const std::string e = simswift::testing::configError([&] { Experiment::parse(mixed, "mixed.yaml"); });
  EXPECT_NE(e.find("mixed.yaml:21: setups[1].robots[1].lola: every robot of a setup ticks alike"), std::string::npos)
      << e;
}

// Unchanged LoLA programs (the facts-only client, opening /tmp/robocup)
// launched for every trial of a 2-worker experiment: each drives its own
// robot, every trial completes, and no socket is left behind.
TEST(V6Experiment, UnchangedProgramsInTwoWorkersEachDriveTheirOwnRobot) {
  const std::string client = std::string(SIMSWIFT_BINARY_DIR) + "/lola-client";
  const std::string file =
      "name: v6clients\nseed: 7\ntime_limit: 2\ntrials_per_position: 2\nstart: {penalised: 0.5}\n"
      "balls:\n  - {position: 1, x: 2.25, y: 0.0}\n"
      "setups:\n  - name: clients\n    behaviour: script\n"
      "    program: {command: [\"" + client + "\", \"-\", \"0\", hold]}\n"
      "    robots:\n"
      "      - {team: 19, player: 2, x: -3.0, y: 1.0, theta: 0, lola: {}, actions: []}\n"
      "      - {team: 19, player: 3, x: -3.0, y: -1.0, theta: 0, lola: {}, actions: []}\n";
  const Experiment e = Experiment::parse(file, "v6clients.yaml");
  const std::string dir = exptest::freshDir("clients");
  const simswift::experiment::BatchOutcome o = exptest::runInto(e, dir, 2);
  ASSERT_TRUE(o.assembled) << o.message;
  EXPECT_EQ(o.ran, 2);
  EXPECT_EQ(o.failed, 0) << o.message;
  // Every trial: not failed, and both robots stood on their held joints
  // (no fall) for the 2.5 s.
  const std::string csv = exptest::readAll(dir + "/results.csv");
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split(line);
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    const std::vector<std::string> f = split(line);
    ASSERT_EQ(f.size(), header.size()) << line;
    for (size_t i = 0; i < f.size(); ++i) {
      if (header[i] == "failed") {
        EXPECT_EQ(f[i], "") << line;
      }
      if (header[i] == "robot1_falls" || header[i] == "robot2_falls") {
        EXPECT_EQ(f[i], "0") << header[i] << ": " << line;
      }
    }
  }
  EXPECT_EQ(rows, 2) << csv;
  // Nothing left behind: a socket named by a process that has ended
  // (simswift-lola-p<pid>-<tag>). One of a live process is another test's,
  // which ctest may run beside this one.
  for (const auto& entry : std::filesystem::directory_iterator("/dev/shm")) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("simswift-lola-p", 0) != 0) continue;
    const long pid = std::strtol(name.c_str() + std::strlen("simswift-lola-p"), nullptr, 10);
    EXPECT_FALSE(pid <= 0 || (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH))
        << "left behind: " << entry.path();
  }
}
