// Experiments on launched robot programs (program: {command: [...]}):
// byte-identical to the builtin program's results with one and two workers
// (the lock-step makes the process boundary invisible; two workers run the
// same team and player at once in private /dev/shm namespaces), a crashing
// program fails only its trial, and kill -9 of a batch leaves no process
// and no shared-memory object behind.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "ExperimentTestUtil.hpp"
#include "app/experiment/Batch.hpp"
#include "app/experiment/PrivateShm.hpp"

namespace fs = std::filesystem;
using exptest::readAll;
using Clock = std::chrono::steady_clock;

namespace {

int runExperiment(const std::string& args, const std::string& err_file) {
  const std::string cmd = exptest::simswiftBinary() + " experiment " + args + " --progress none 2> '" + err_file + "'";
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

std::string shipped(const std::string& name) { return std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/" + name; }

// Objects in the machine's /dev/shm whose name ends in `suffix`.
int shmObjects(const std::string& suffix) {
  int n = 0;
  for (const auto& f : fs::directory_iterator("/dev/shm")) {
    const std::string name = f.path().filename().string();
    if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) ++n;
  }
  return n;
}

// Processes whose command line mentions `text`.
int processesMentioning(const std::string& text) {
  int n = 0;
  for (const auto& p : fs::directory_iterator("/proc")) {
    const std::string cmdline = readAll(p.path().string() + "/cmdline");
    if (cmdline.find(text) != std::string::npos) ++n;
  }
  return n;
}

// A tiny experiment whose robots (team 97: 97 x 11 + 2 = /libagent-memory1069)
// run launched simswift-agents; two setups, `trials` per position.
std::string tinyLaunched(int trials, double limit, const std::string& crash_setup_program = "") {
  std::string s = exptest::tinyExperiment(trials, limit);
  s.replace(s.find("{team: 19, player: 2"), 20, "{team: 97, player: 2");
  s += "    program: {command: [" + std::string(SIMSWIFT_BINARY_DIR) + "/simswift-agent, --config, \"{config}\"]}\n";
  if (!crash_setup_program.empty())
    s += "  - name: crasher\n"
         "    behaviour: script\n"
         "    program: " + crash_setup_program + "\n"
         "    robots:\n"
         "      - {team: 97, player: 2, x: -0.5, y: 0.0, theta: 0.0, actions: [{t: 0.3, action: stand}]}\n";
  return s;
}

}  // namespace

// The default experiment, every robot a launched simswift-agent: results.csv
// and tracks.csv byte-identical to the builtin run, with --jobs 1 and 2
// (30 trials, seed 2017). Heavy (about 3 min in Release): not in the
// sanitizer builds, which run ExternalExperiment.TwoTrials... instead.
TEST(ExternalExperimentFull, QuickIsByteIdenticalToBuiltinWithOneAndTwoJobs) {
  const std::string d = exptest::freshDir("quick");
  ASSERT_EQ(runExperiment(shipped("findball_quick.yaml") + " --out " + d + "/builtin --jobs 2", d + "/b.txt"), 0)
      << readAll(d + "/b.txt");
  for (const char* jobs : {"1", "2"}) {
    const std::string out = d + "/external" + jobs;
    ASSERT_EQ(runExperiment(shipped("findball_quick_external.yaml") + " --out " + out + " --jobs " + jobs,
                            d + "/e.txt"),
              0)
        << readAll(d + "/e.txt");
    EXPECT_EQ(readAll(out + "/results.csv"), readAll(d + "/builtin/results.csv")) << "--jobs " << jobs;
    EXPECT_EQ(readAll(out + "/tracks.csv"), readAll(d + "/builtin/tracks.csv")) << "--jobs " << jobs;
    EXPECT_TRUE(exptest::fileExists(out + "/trials/0/t19p2.log"));
    EXPECT_TRUE(exptest::fileExists(out + "/trials/29/t19p4.robot.yaml"));
  }
  EXPECT_FALSE(readAll(d + "/builtin/results.csv").empty());
}

// The same on two trials (one per setup: 2016 and 2017 behaviours), for the
// sanitizer builds: two workers at once on the same team and player.
TEST(ExternalExperiment, TwoTrialsMatchTheBuiltinOnesWithTwoWorkers) {
  const std::string d = exptest::freshDir("two");
  ASSERT_EQ(runExperiment(shipped("findball_quick.yaml") + " --out " + d + "/b --shard 1/15 --jobs 2", d + "/b.txt"),
            0)
      << readAll(d + "/b.txt");
  ASSERT_EQ(runExperiment(shipped("findball_quick_external.yaml") + " --out " + d + "/e --shard 1/15 --jobs 2",
                          d + "/e.txt"),
            0)
      << readAll(d + "/e.txt");
  for (int t : {0, 15}) {
    const std::string row = readAll(simswift::experiment::trialFile(d + "/b", t, ".csv"));
    EXPECT_FALSE(row.empty());
    EXPECT_EQ(readAll(simswift::experiment::trialFile(d + "/e", t, ".csv")), row) << "trial " << t;
    EXPECT_EQ(readAll(simswift::experiment::trialFile(d + "/e", t, ".tracks.csv")),
              readAll(simswift::experiment::trialFile(d + "/b", t, ".tracks.csv")));
  }
}

// A program that segfaults 1 s into its trial fails that trial (results.csv
// says how, the report lists it apart); the other trials finish.
TEST(ExternalExperiment, ACrashingProgramFailsOnlyItsTrial) {
  const std::string d = exptest::freshDir("crash");
  const std::string crasher = "{command: [" + std::string(SIMSWIFT_BINARY_DIR) +
                              "/libagent2017-client, --team, \"{team}\", --player, \"{player}\", --ticks, 100000, "
                              "--stand, --crash-at, 100]}";
  exptest::writeAll(d + "/x.yaml", tinyLaunched(1, 7.0, crasher));  // 2 setups x 2 balls x 1 = 4 trials
  ASSERT_EQ(runExperiment(d + "/x.yaml --out " + d + "/out --jobs 2", d + "/err.txt"), 0) << readAll(d + "/err.txt");
  const std::string results = readAll(d + "/out/results.csv");
  EXPECT_NE(results.find("failed,robot1_player"), std::string::npos) << results;
  // Trials 2 and 3 are the crasher's (setup-major order).
  int failed = 0;
  size_t pos = 0;
  while ((pos = results.find("killed by signal 11 (Segmentation fault)", pos)) != std::string::npos) ++failed, ++pos;
  EXPECT_EQ(failed, 2) << results;
  EXPECT_NE(results.find(",t97p2: program killed by signal 11 (Segmentation fault),"), std::string::npos) << results;
  EXPECT_NE(results.find("\n0,walker,1,"), std::string::npos);
  // The walker's first trial ran and found position 1 (field 6: found).
  const size_t row = results.find("\n0,walker,1,0,");
  ASSERT_NE(row, std::string::npos) << results;
  size_t f = row + 1;
  for (int k = 0; k < 5; ++k) f = results.find(',', f) + 1;
  EXPECT_EQ(results.substr(f, 2), "1,") << results;
  EXPECT_NE(readAll(d + "/out/report.md").find("**2 trial(s) failed**"), std::string::npos);
  EXPECT_NE(readAll(d + "/out/trials/2/t97p2.log").find("crashing at tick 100"), std::string::npos);
}

// kill -9 of the whole batch mid-run: the launched programs go with their
// workers (PR_SET_PDEATHSIG), nothing of team 97's is ever in the machine's
// /dev/shm (each worker's is private), and the resumed run equals a run
// with one worker.
TEST(ExternalExperiment, KillMinus9LeavesNothingAndResumeEqualsOneWorker) {
  std::string why;
  if (!simswift::experiment::privateShmAvailable(&why)) GTEST_SKIP() << "no private /dev/shm here: " << why;
  const std::string d = exptest::freshDir("kill");
  exptest::writeAll(d + "/k.yaml", tinyLaunched(2, 60.0));  // 4 trials; position 2 is never found: 60 s each
  const std::string out = d + "/out";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    setpgid(0, 0);
    const std::string bin = exptest::simswiftBinary();
    freopen("/dev/null", "w", stderr);
    execl(bin.c_str(), bin.c_str(), "experiment", (d + "/k.yaml").c_str(), "--out", out.c_str(), "--jobs", "2",
          "--progress", "none", static_cast<char*>(nullptr));
    _exit(127);
  }
  setpgid(pid, pid);
  // Kill once both workers' programs run (each has written its setup file).
  int seen_shm = 0;
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  while (!(exptest::fileExists(out + "/trials/0/t97p2.robot.yaml") &&
           exptest::fileExists(out + "/trials/1/t97p2.robot.yaml")) &&
         Clock::now() < deadline) {
    seen_shm += shmObjects("1069");
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  seen_shm += shmObjects("1069");
  kill(-pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  ASSERT_FALSE(exptest::fileExists(out + "/results.csv")) << "the run ended before the kill: test proves nothing";
  const auto gone = Clock::now() + std::chrono::seconds(5);
  while (processesMentioning(out + "/trials") > 0 && Clock::now() < gone)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(processesMentioning(out + "/trials"), 0) << "a launched program outlived its killed worker";
  EXPECT_EQ(seen_shm, 0) << "a trial's objects were in the machine's /dev/shm";
  EXPECT_EQ(shmObjects("1069"), 0);

  ASSERT_EQ(runExperiment(d + "/k.yaml --out " + out + " --jobs 2", d + "/resume.txt"), 0) << readAll(d + "/resume.txt");
  ASSERT_EQ(runExperiment(d + "/k.yaml --out " + d + "/one --jobs 1", d + "/one.txt"), 0) << readAll(d + "/one.txt");
  EXPECT_EQ(readAll(out + "/results.csv"), readAll(d + "/one/results.csv"));
  EXPECT_FALSE(readAll(d + "/one/results.csv").empty());
  EXPECT_EQ(shmObjects("1069"), 0);
}

// kill -9 of the batch's own process alone (not its group): its workers die
// with it, and their launched programs with them (PR_SET_PDEATHSIG on each
// level). Before issue 34 the workers, and so their simswift-agents, ran on
// under pid 1.
TEST(ExternalExperiment, KillMinus9OfTheBatchAloneEndsWorkersAndPrograms) {
  const std::string d = exptest::freshDir("alone");
  std::string text = tinyLaunched(2, 3600.0);  // position 2 is never found: 3600 s simulated
  const std::string found = "  - {position: 1, x: 0.7, y: 0.0}\n";
  text.erase(text.find(found), found.size());  // so every trial runs far longer than this test waits
  exptest::writeAll(d + "/k.yaml", text);
  const std::string out = d + "/out";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    setpgid(0, 0);  // for the cleanup only
    const std::string bin = exptest::simswiftBinary();
    if (!freopen("/dev/null", "w", stderr)) _exit(126);
    execl(bin.c_str(), bin.c_str(), "experiment", (d + "/k.yaml").c_str(), "--out", out.c_str(), "--jobs", "2",
          "--progress", "none", static_cast<char*>(nullptr));
    _exit(127);
  }
  setpgid(pid, pid);
  // Once a program runs (it has written its setup file), the workers are known.
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  while (!exptest::fileExists(out + "/trials/0/t97p2.robot.yaml") && Clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // its simswift-agent started
  const std::vector<pid_t> workers = exptest::childrenOf(pid);
  ASSERT_FALSE(workers.empty()) << "no worker";
  const int programs = processesMentioning(out + "/trials");
  kill(pid, SIGKILL);  // the batch alone
  waitpid(pid, nullptr, 0);
  const std::vector<pid_t> left = exptest::stillAliveAfter(workers, 5.0);
  const auto gone = Clock::now() + std::chrono::seconds(5);
  while (processesMentioning(out + "/trials") > 0 && Clock::now() < gone)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const int programs_left = processesMentioning(out + "/trials");
  kill(-pid, SIGKILL);  // the test's own cleanup of anything left (the programs go with their workers)
  EXPECT_GT(programs, 0) << "no launched program was running: the test proves nothing about them";
  EXPECT_TRUE(left.empty()) << left.size() << " worker(s) outlived their killed batch";
  EXPECT_EQ(programs_left, 0) << "a launched program outlived its batch";
}
