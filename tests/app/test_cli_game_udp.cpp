// `simswift run` with game: {udp: on}, as a user runs it: a bad value exits
// 2 naming file, line and field; a good run sends the GameController packets
// a plain UDP listener hears, and says so in its summary.
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/Sockets.hpp"

namespace {

namespace fs = std::filesystem;

struct ScenarioRun {
  int code = -1;
  std::string out;  // stdout and stderr
};

ScenarioRun runScenario(const std::string& scenario) {
  const std::string cmd = std::string(SIMSWIFT_BINARY_DIR) + "/simswift run " + scenario + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  ScenarioRun r;
  char buf[512];
  while (fgets(buf, sizeof buf, p)) r.out += buf;
  const int st = pclose(p);
  r.code = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  return r;
}

std::string writeScenario(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("simswift_cli_udp_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

const std::string kOne = "duration: 1\nnoise: off\nrobots:\n  - {team: 19, player: 1, x: -1, y: 0}\n";

}  // namespace

TEST(CliGameUdp, BadValueExitsTwoNamingFileLineAndField) {
  const std::string s = writeScenario("bad_udp.yaml", kOne + "game: {udp: on, return_port: 3838}\n");
  const ScenarioRun r = runScenario(s);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find(s + ":5: game.return_port: must differ from port"), std::string::npos) << r.out;
}

TEST(CliGameUdp, RunSendsPacketsAListenerHears) {
  const simswift::testing::UdpListener listener;
  ASSERT_GT(listener.port, 0);
  const std::string s = writeScenario("udp.yaml", kOne + "game: {udp: on, return_port: 0, port: " +
                                              std::to_string(listener.port) + "}\n");
  const ScenarioRun r = runScenario(s);
  EXPECT_EQ(r.code, 0) << r.out;
  // t = 0, 0.5 and 1 s of simulated time.
  EXPECT_NE(r.out.find("| gc udp 3 sent |"), std::string::npos) << r.out;
  const std::vector<std::vector<unsigned char>> heard = listener.drain();
  for (const auto& p : heard) {
    EXPECT_EQ(p.size(), 588u);
    EXPECT_EQ(std::string(p.begin(), p.begin() + std::min<size_t>(4, p.size())), "RGme");
  }
  EXPECT_EQ(heard.size(), 3u);
}
