// What a launched program sees (sim/programs/ProgramView.hpp): its PID
// namespace (a kill -9 of simswift ends a wrapper script's grandchild), its
// own /tmp (two programs' lock files never meet), the robot's files, and a
// bad `files:` entry refused with file:line.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "sim/programs/MountNamespace.hpp"
#include "sim/programs/ProgramView.hpp"
#include "sim/runner/Runner.hpp"
#include "tests/runner/RunnerTestUtil.hpp"
#include "tests/support/Attach.hpp"
#include "tests/support/ConfigErrors.hpp"
#include "tests/support/Shell.hpp"

namespace fs = std::filesystem;
using simswift::runner::RunOptions;
using simswift::runner::Runner;
using simswift::runner::Scenario;
using simswift::testing::exitCodeOf;
using simswift::testing::startAttach;

namespace {

using runnertest::kBin;
using simswift::testing::readText;

std::string viewTempDir(const std::string& tag) {
  const fs::path d = fs::temp_directory_path() / ("simswift_view_" + tag + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d.string();
}

// The pids of processes whose command line holds `marker`.
int processesNamed(const std::string& marker) {
  int n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator("/proc", ec)) {
    // A process may end while it is read (ESRCH): it is then not counted.
    const int fd = open((e.path() / "cmdline").c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) continue;
    std::string cmd;
    char buf[4096];
    for (ssize_t got; (got = read(fd, buf, sizeof buf)) > 0;) cmd.append(buf, static_cast<size_t>(got));
    close(fd);
    if (cmd.find(marker) != std::string::npos) ++n;
  }
  return n;
}

// Skips (saying why) where the machine gives no namespaces: there a
// launched program has none of this view (docs/porting.md).
#define REQUIRE_NAMESPACES()                                                                   \
  do {                                                                                         \
    const auto ns = simswift::programs::mountNamespaceSupport();                               \
    if (!ns.available) GTEST_SKIP() << "this machine gives no namespaces: " << ns.why;         \
  } while (0)

}  // namespace

// A team program started through a wrapper script whose child outlives it
// in the background: kill -9 of simswift ends the grandchild too (its PID
// namespace's init dies with simswift), within 2 s. Before: only the
// direct child had PR_SET_PDEATHSIG and the grandchild ran on.
TEST(ProgramView, KillNineOfSimswiftEndsAWrapperScriptsGrandchild) {
  REQUIRE_NAMESPACES();
  const std::string d = viewTempDir("kill");
  // Two processes that wait on nothing timed (a sleep would end at once
  // before the first packet: docs/shim.md): each blocks opening a FIFO
  // nobody writes. Their command line carries a marker no other process
  // has; the wrapper's own command line spells it through $m, so it does not.
  const std::string marker = "kill-test-" + std::to_string(getpid());
  {
    std::ofstream y(d + "/wrapper.yaml");
    y << "duration: 600\nattach_timeout: 60\nprogram_logs: " << d << "/logs\nrobots:\n"
      << "  - {team: 39, player: 1, x: -1, y: 0, program: {command: [sh, -c, 'm=kill-test; mkfifo /tmp/w; cat /tmp/w $m-"
      << getpid() << " & cat /tmp/w $m-" << getpid() << "; wait']}}\n";
  }
  const std::string simswift = kBin + "/simswift";
  const pid_t sim = fork();
  if (sim == 0) {
    const int fd = open((d + "/run.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) dup2(fd, 1), dup2(fd, 2);
    execl(simswift.c_str(), simswift.c_str(), "run", (d + "/wrapper.yaml").c_str(), "--quiet", nullptr);
    _exit(127);
  }
  bool started = false;
  for (int i = 0; i < 1000 && !started; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    started = processesNamed(marker) == 2;  // the background cat and the foreground one
  }
  if (!started) kill(sim, SIGKILL), waitpid(sim, nullptr, 0);
  ASSERT_TRUE(started) << readText(d + "/run.log");
  kill(sim, SIGKILL);
  int status = 0;
  ASSERT_EQ(waitpid(sim, &status, 0), sim);
  for (int i = 0; i < 200 && processesNamed(marker) > 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(processesNamed(marker), 0) << "the wrapper's children outlived simswift";
  fs::remove_all(d);
}

// Two unchanged programs that take the same lock file in /tmp (noclobber:
// the second would fail if they shared it) and check the robot's files,
// then run simswift-agent: a run with both ends normally. Each sees its own
// /tmp, the hwmon temperatures B-Human opens, LoLA's executable at NaoTH's
// two paths, a writable /home/nao, and the scenario's files (content and a
// folder mapped in); the machine's /tmp stays untouched.
TEST(ProgramView, TwoProgramsTakeTheSameLockFileAndSeeTheRobotsFiles) {
  REQUIRE_NAMESPACES();
  const std::string d = viewTempDir("tmp");
  const std::string lock = "/tmp/simswift-view-test-" + std::to_string(getpid()) + ".pid";
  fs::create_directories(d + "/config");
  std::ofstream(d + "/config/naoth.cfg") << "[team]\nnumber=71\n";
  // Written as a team's start-up checks would be: each failure its own exit
  // status. $1: the player, $2: the {config} file.
  std::ofstream(d + "/check.sh")
      << "set -C\n"
      << "echo $$ > " << lock << " || exit 3\n"
      << "for i in 2 3 4 5; do test \"$(cat /sys/class/hwmon/hwmon1/temp\"$i\"_input)\" = 50000 || exit 4; done\n"
      << "test -x /opt/aldebaran/bin/lola -a -x /usr/bin/lola || exit 5\n"
      << "echo hi > /home/nao/written || exit 6\n"
      << "test \"$(cat /etc/simswift-view-test)\" = \"robot $1\" || exit 7\n"
      << "grep -q number=71 /home/nao/Config/naoth.cfg || exit 8\n"
      << "test $(ls /proc | grep -c '^[0-9]') -le 8 || exit 9\n"  // its PID namespace's processes only
      << "sleep 0.2\n"
      << "exec " << kBin << "/simswift-agent --config \"$2\"\n";
  std::ostringstream y;
  y << "duration: 0.3\nseed: 3\nprogram_logs: " << d << "/logs\nrobots:\n";
  for (int p = 1; p <= 2; ++p)
    y << "  - {team: 71, player: " << p << ", x: -1, y: " << p << ", posture: stand, program: {command: [sh, "
      << d << "/check.sh, '{player}', '{config}'], files: {/etc/simswift-view-test: 'robot " << p
      << "', /home/nao/Config: {from: config}}}}\n";
  std::ofstream(d + "/two.yaml") << y.str();
  RunOptions o;
  o.progress = false;
  Runner r(Scenario::loadFile(d + "/two.yaml"));
  EXPECT_NO_THROW(r.run(o)) << readText(d + "/logs/t71p1.log") << readText(d + "/logs/t71p2.log");
  EXPECT_NE(access(lock.c_str(), F_OK), 0) << "a program wrote into the machine's /tmp";
  // Each program's /tmp and /home/nao are folders of the run.
  EXPECT_EQ(readText(d + "/logs/t71p1.view/tmp/" + fs::path(lock).filename().string()), "2\n");
  EXPECT_EQ(readText(d + "/logs/t71p2.view/home/written"), "hi\n");
  fs::remove_all(d);
}

TEST(ProgramView, BadFileEntriesAreRefusedWithFileAndLine) {
  auto parse = [](const std::string& files) {
    return simswift::testing::configError([&] {
      Scenario::parse("robots:\n  - {team: 71, player: 1,\n     program: {command: [x],\n       files: " + files +
                          "}}\n",
                      "files.yaml");
    });
  };
  EXPECT_NE(parse("{/proc/cpuinfo: x}").find("files.yaml:4: robots[0].program.files./proc/cpuinfo: cannot be under"),
            std::string::npos)
      << parse("{/proc/cpuinfo: x}");
  EXPECT_NE(parse("{etc/x: x}").find("files.yaml:4:"), std::string::npos) << parse("{etc/x: x}");
  EXPECT_NE(parse("{/etc/x: {from: /no/such/folder}}").find("no such file or folder: /no/such/folder"),
            std::string::npos);
  EXPECT_NE(parse("{/etc/x: [1]}").find("expected the file's content"), std::string::npos);
  EXPECT_NE(parse("{/opt/a: {from: /}, /opt/a/b: x}").find("is inside /opt/a"), std::string::npos);
  EXPECT_NE(parse("{/tmp/robocup: x}").find("the robot's LoLA socket"), std::string::npos);
}

// A V5 robot (libagent's block) whose program is external: `simswift
// attach --team T --player P` needs no socket (the robot's clock page says
// its body) and starts its command in the view the run holds for the robot,
// as a launched program's: its PID namespace, files and /tmp; the libagent
// client started so holds the robot as the launched one does (the same hash).
// Team 38: no other test's (ctest runs tests side by side; a robot's objects
// are named by its team and player).
TEST(ProgramView, AttachStartsAV5ProgramInItsRobotsView) {
  REQUIRE_NAMESPACES();
  const std::string d = viewTempDir("v5attach");
  const std::string client = kBin + "/libagent2017-client";
  const auto scenario = [&](const std::string& program) {
    std::ostringstream y;
    y << "duration: 0.5\nseed: 3\nattach_timeout: 20\nprogram_logs: " << d << "/logs\nrobots:\n"
      << "  - {team: 38, player: 1, x: -1, y: 1, libagent: {release: 2017}, program: " << program << "}\n";
    return Scenario::parse(y.str(), d + "/v5.yaml");
  };
  RunOptions o;
  o.progress = false;
  uint64_t launched = 0;
  {
    Runner r(scenario("{command: [" + client + ", --team, '{team}', --player, '{player}', --ticks, 50, --stand]}"));
    launched = r.run(o).hash;
  }
  Runner r(scenario("external"));
  r.start();
  EXPECT_EQ(exitCodeOf(startAttach(38, 1, {"/bin/sh", "-c",
                           "echo pid $$; cat /sys/class/hwmon/hwmon1/temp3_input; test -e /tmp/robocup || "
                           "echo no robocup; echo hi > /home/nao/written"},
                          d + "/sh.log")),
            0)
      << readText(d + "/sh.log");
  EXPECT_EQ(readText(d + "/sh.log"), "pid 2\n50000\nno robocup\n");
  EXPECT_EQ(readText(d + "/logs/t38p1.view/home/written"), "hi\n");
  const pid_t program = startAttach(38, 1, {client, "--team", "38", "--player", "1", "--ticks", "50", "--stand"}, d + "/client.log");
  EXPECT_EQ(r.run(o).hash, launched);
  EXPECT_EQ(exitCodeOf(program), 0) << readText(d + "/client.log");
  fs::remove_all(d);
}
