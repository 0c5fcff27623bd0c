// The simswift program: every input error, whichever file it is in, exits
// with code 2 and a message naming the file and the line; never an abort.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sim/bridge/BodyHost.hpp"
#include "tests/support/Shell.hpp"

namespace {

namespace fs = std::filesystem;

struct Result {
  int code = -1;
  std::string err;
};

Result run(const std::string& args) {
  const std::string cmd = std::string(SIMSWIFT_BINARY_DIR) + "/simswift run " + args + " --quiet 2>&1 >/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  Result r;
  char buf[512];
  while (fgets(buf, sizeof buf, p)) r.err += buf;
  const int st = pclose(p);
  r.code = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  return r;
}

std::string write(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("simswift_cli_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

std::string shipped(const char* rel) {
  std::ifstream in(std::string(SIMSWIFT_SOURCE_DIR) + "/" + rel);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void expectInputError(const std::string& args, const std::string& file_line) {
  const Result r = run(args);
  EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(file_line), std::string::npos) << args << "\n" << r.err;
}

}  // namespace

TEST(Cli, BadScenarioFieldAndModelExitTwoNamingFileAndLine) {
  const std::string one = "robots:\n  - {team: 0, player: 1, x: -1, y: 0}\n";
  const std::string s = write("bad.yaml", "duration: 1e12\n" + one);
  expectInputError(s, s + ":1: duration:");

  const std::string f = write("short_post.yaml", "field:\n  goal:\n    post_height: 0.04\n");
  const std::string sf = write("with_field.yaml", "field: short_post.yaml\nduration: 0.1\n" + one);
  expectInputError(sf, f + ":3: field.goal.post_height:");

  std::string urdf = shipped("models/nao_v5.urdf");
  urdf.replace(urdf.find("<axis xyz=\"0 1 0\"/>"), 19, "<axis xyz=\"0 0 2e154\"/>");
  const std::string m = write("bad.urdf", urdf);
  const std::string sm = write("with_model.yaml", "model: bad.urdf\nduration: 0.1\n" + one);
  expectInputError(sm, m + ":");
  EXPECT_NE(run(sm).err.find("<axis xyz>"), std::string::npos);

  // --model and --field override the scenario's.
  expectInputError(write("plain.yaml", "duration: 0.1\n" + one) + " --model " + m, m + ":");
  expectInputError(write("plain2.yaml", "duration: 0.1\n" + one) + " --field " + f, f + ":3:");

  // A robot at x = 1e308 aborted ODE once.
  const std::string far = write("far.yaml", "robots:\n  - {team: 0, player: 1, x: 1e308}\n");
  expectInputError(far, far + ":2: robots[0].x:");
  // A directory as the scenario.
  expectInputError(fs::path(s).parent_path().string(), fs::path(s).parent_path().string() + ":1: is a directory");
}

// The version printed is project()'s in CMakeLists.txt (it said 0.1 while
// the project was 0.2.0).
TEST(Cli, VersionIsTheProjectsVersion) {
  FILE* p = popen((std::string(SIMSWIFT_BINARY_DIR) + "/simswift --version 2>&1").c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string out;
  char buf[256];
  while (fgets(buf, sizeof buf, p)) out += buf;
  const int st = pclose(p);
  EXPECT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0) << out;
  EXPECT_EQ(out, std::string("simswift ") + SIMSWIFT_VERSION + "\n");
}

TEST(Cli, GoodScenarioRunsAndExitsZero) {
  const std::string s =
      write("good.yaml", "duration: 0.05\nrobots:\n  - {team: 0, player: 1, x: -1, y: 0}\n");
  const Result r = run(s);
  EXPECT_EQ(r.code, 0) << r.err;
}

// docs/runner.md, "Debugging in gdb": a robot thread held 3 s at a
// breakpoint with a 1 s watchdog; the run still ends normally with the hash
// of a run without gdb (the runner waits for every thread each tick).
TEST(Cli, BreakpointInGdbDoesNotTripTheWatchdog) {
  if (std::system("command -v gdb >/dev/null 2>&1") != 0) GTEST_SKIP() << "gdb not installed";
  const std::string scenario = std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/walk_one.yaml";
  const std::string args = scenario + " --duration 1 --watchdog 1 --quiet";
  auto capture = [](const std::string& cmd) {
    FILE* p = popen(cmd.c_str(), "r");
    std::string out;
    char buf[512];
    while (fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
    return out;
  };
  auto hashOf = [](const std::string& out) {
    const size_t h = out.find("| hash ");
    return h == std::string::npos ? std::string("none") : out.substr(h + 7, 16);
  };
  const std::string plain = capture(std::string(SIMSWIFT_BINARY_DIR) + "/simswift run " + args);
  // LeakSanitizer cannot run under ptrace (sanitizer builds): off for gdb.
  const std::string gdb = capture(
      "ASAN_OPTIONS=detect_leaks=0 gdb -q -batch -ex 'set pagination off' -ex 'break agent::motion::Walk2014Generator::tick' -ex run "
      "-ex 'shell sleep 3' -ex delete -ex continue --args " +
      std::string(SIMSWIFT_BINARY_DIR) + "/simswift run " + args + " 2>&1");
  EXPECT_NE(gdb.find("hit Breakpoint 1"), std::string::npos) << gdb;
  EXPECT_EQ(gdb.find("did not answer"), std::string::npos) << gdb;
  EXPECT_NE(gdb.find("exited normally"), std::string::npos) << gdb;
  EXPECT_EQ(hashOf(gdb), hashOf(plain)) << gdb << "\n" << plain;
}

// simswift clean: the objects of a SIGKILLed simulator go; a live
// simulator's robot stays and its pid is named.
TEST(Cli, CleanRemovesWhatAKilledRunLeftAndNamesLiveOwners) {
  namespace sb = simswift::bridge;
  // The child says when its robot is whole (the extension's owner written
  // last): killed before that, the objects are a set-up, not a killed run's.
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  if (child == 0) {
    close(ready[0]);
    sb::BodyHost host(93, 4, sb::BodyHost::Mode::Named);
    (void)!write(ready[1], "r", 1);
    pause();
    _exit(0);
  }
  close(ready[1]);
  char byte = 0;
  ASSERT_EQ(read(ready[0], &byte, 1), 1);
  close(ready[0]);
  const std::string memory = "/dev/shm/libagent-memory" + std::to_string(93 * 11 + 4);
  ASSERT_TRUE(fs::exists(memory));
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  ASSERT_TRUE(fs::exists(memory));  // a SIGKILL leaves it
  sb::BodyHost live(93, 5, sb::BodyHost::Mode::Named);
  FILE* p = popen((std::string(SIMSWIFT_BINARY_DIR) + "/simswift clean --team 93 --player 4 2>&1").c_str(), "r");
  std::string out;
  char buf[256];
  while (fgets(buf, sizeof buf, p)) out += buf;
  EXPECT_EQ(WEXITSTATUS(pclose(p)), 0) << out;
  EXPECT_FALSE(fs::exists(memory)) << out;
  EXPECT_NE(out.find("removed 1 robot(s)"), std::string::npos) << out;
  p = popen((std::string(SIMSWIFT_BINARY_DIR) + "/simswift clean --team 93 --player 5 2>&1").c_str(), "r");
  out.clear();
  while (fgets(buf, sizeof buf, p)) out += buf;
  pclose(p);
  EXPECT_NE(out.find("in use by a running simswift (pid " + std::to_string(getpid()) + ")"), std::string::npos) << out;
  EXPECT_TRUE(fs::exists("/dev/shm/libagent-memory" + std::to_string(93 * 11 + 5)));
}

// The one seed reader on both programs' command lines: the largest 64-bit
// seed is taken, one beyond it is refused with exit 2 naming the range.
TEST(Cli, TheSeedTakesEverySixtyFourBitValue) {
  const std::string scenario = std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/stand_one.yaml";
  const Result max = run(scenario + " --seed 18446744073709551615 --duration 0.02");
  EXPECT_EQ(max.code, 0) << max.err;
  const Result over = run(scenario + " --seed 18446744073709551616 --duration 0.02");
  EXPECT_EQ(over.code, 2) << over.err;
  EXPECT_NE(over.err.find("--seed: must be a whole number in [0, 18446744073709551615]"), std::string::npos)
      << over.err;
  FILE* p = popen((std::string(SIMSWIFT_BINARY_DIR) + "/simswift-agent --seed 1e3 2>&1").c_str(), "r");
  std::string agent_err;
  char buf[512];
  while (fgets(buf, sizeof buf, p)) agent_err += buf;
  const int st = pclose(p);
  EXPECT_EQ(WIFEXITED(st) ? WEXITSTATUS(st) : -1, 2) << agent_err;
  EXPECT_NE(agent_err.find("--seed: must be a whole number in [0, 18446744073709551615] (got '1e3')"),
            std::string::npos)
      << agent_err;
}

// A scenario file's seed reaches the run unchanged, all 64 bits (it was a
// YAML number, exact only up to 2^53): the run's hash is that of the same
// seed given as --seed, and not that of its neighbour. Bad seeds exit 2
// naming the file, line and field.
TEST(Cli, AScenarioFilesSeedReachesTheRunUnchanged) {
  const std::string body = "duration: 0.5\nnoise: on\nrobots:\n  - {team: 19, player: 1, x: -1, y: 0, posture: stand}\n";
  auto hashOf = [](const std::string& args) {
    const simswift::testing::ShellResult r =
        simswift::testing::shell(std::string(SIMSWIFT_BINARY_DIR) + "/simswift run " + args + " --quiet");
    EXPECT_EQ(r.code, 0) << r.output;
    const size_t at = r.output.find("hash ");
    return at == std::string::npos ? r.output : r.output.substr(at + 5, 16);
  };
  const std::string max = write("seed_max.yaml", "seed: 18446744073709551615\n" + body);
  const std::string one = write("seed_one.yaml", "seed: 1\n" + body);
  const std::string from_file = hashOf(max);
  EXPECT_EQ(from_file.size(), 16u) << from_file;
  EXPECT_EQ(from_file, hashOf(one + " --seed 18446744073709551615"));
  EXPECT_NE(from_file, hashOf(one + " --seed 18446744073709551614"));
  for (const char* bad : {"1.5", "-1", "18446744073709551616"}) {
    const std::string s = write("seed_bad.yaml", std::string("seed: ") + bad + "\n" + body);
    expectInputError(s, s + ":1: seed: must be a whole number in [0, 18446744073709551615] (got '" + bad + "')");
  }
}
