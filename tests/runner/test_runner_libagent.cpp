// The libagent interface end to end: a robot program as a team brings it
// (tests/libagent_client: each rUNSWift release's block declared from its public layout, no
// project header, libagent's protocol only) runs in lock-step, started
// before or after the simulator, with the same state hash as the same moves
// done in-process; FSRs in kg; free-running mode sits a silent robot down;
// a program outlives a SIGKILLed simulator by < 2 s; SPL team numbers.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <semaphore.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "common/libagent/SharedNames.hpp"
#include "common/libagent/SimExtension.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"
#include "tests/runner/RunnerTestUtil.hpp"

namespace al = common::libagent;
namespace ap = agent::program;
using simswift::runner::RunOptions;
using simswift::runner::Runner;
using simswift::runner::RunStats;
using simswift::runner::Scenario;
using simswift::runner::TeamColour;
using Clock = std::chrono::steady_clock;

namespace {

using runnertest::kBin;
using runnertest::quiet;

// Starts `args` (argv[0] = path); stdout / stderr to files if given.
pid_t spawn(const std::vector<std::string>& args, const std::string& out = "", const std::string& err = "") {
  const pid_t pid = fork();
  if (pid != 0) return pid;
  if (!out.empty()) {
    const int fd = open(out.c_str(), O_CREAT | O_TRUNC | O_WRONLY, 0600);
    dup2(fd, 1);
  }
  if (!err.empty()) {
    const int fd = open(err.c_str(), O_CREAT | O_TRUNC | O_WRONLY, 0600);
    dup2(fd, 2);
  }
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  _exit(127);
}

// Exit status, or -1 if still running after `timeout_s` (then killed).
int waitExit(pid_t pid, double timeout_s, double* took = nullptr) {
  const auto t0 = Clock::now();
  for (;;) {
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) {
      if (took) *took = std::chrono::duration<double>(Clock::now() - t0).count();
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    if (std::chrono::duration<double>(Clock::now() - t0).count() > timeout_s) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

bool existsInShm(const std::string& name) {
  struct stat st {};
  return stat(("/dev/shm" + name).c_str(), &st) == 0;
}

std::string tmpPath(const std::string& what) {
  return "/tmp/simswift-test-" + std::to_string(getpid()) + "-" + what;
}

Scenario robotScenario(double duration, int team, int player, const std::string& program) {
  Scenario s = Scenario::parse("duration: " + std::to_string(duration) +
                                   "\nseed: 3\nattach_timeout: 20\nwatchdog: 10\nrobots:\n  - {team: " +
                                   std::to_string(team) + ", player: " + std::to_string(player) +
                                   ", x: -1.0, program: " + program + "}\n",
                               "test.yaml");
  return s;
}

std::vector<std::string> clientArgs(int team, int player, long ticks, std::vector<std::string> extra = {}) {
  std::vector<std::string> a = {kBin + "/libagent2017-client", "--team", std::to_string(team), "--player",
                                std::to_string(player), "--ticks", std::to_string(ticks), "--timeout", "20"};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

double modelJoint(Runner& r, const char* name) {
  const simswift::RobotBody& body = r.world().robot(0);
  return body.jointAngle(body.model().jointIndex(name));
}

// The client's moves (tests/libagent_client/libagent_client.cpp), done
// by the in-process robot program with the same float arithmetic. k counts
// ticks from the first (t = 10 ms -> k = 1).
float ramp(long k, long t0, long t1) {
  if (k <= t0) return 0.0f;
  if (k >= t1) return 1.0f;
  return static_cast<float>(k - t0) / static_cast<float>(t1 - t0);
}
struct SameMoves : agent::framework::MotionGenerator {
  al::JointValues hold{};
  void tick(const al::SensorValues& s, int64_t t_us, al::JointValues& out) override {
    namespace J = al::Joints;
    const long k = static_cast<long>(t_us / 10000);
    if (k == 1) {
      hold = s.joints;
      for (float& st : hold.stiffnesses) st = 1.0f;
    }
    al::JointValues cmd = hold;
    cmd.angles[J::HeadYaw] = hold.angles[J::HeadYaw] + 0.5f * ramp(k, 50, 100);
    const float d = 0.2f * (ramp(k, 100, 200) - ramp(k, 250, 350));
    for (int hip : {J::LHipPitch, J::RHipPitch}) cmd.angles[hip] = hold.angles[hip] - d;
    for (int knee : {J::LKneePitch, J::RKneePitch}) cmd.angles[knee] = hold.angles[knee] + 2.0f * d;
    for (int ankle : {J::LAnklePitch, J::RAnklePitch}) cmd.angles[ankle] = hold.angles[ankle] - d;
    out = cmd;
  }
};

}  // namespace

// The unchanged libagent program walks the robot through the scripted head
// and leg move in lock-step. Started before the simulator (it creates the
// objects, the simulator adopts them) and after it, the state hash is the
// same, and equal to the in-process program doing the same moves.
TEST(LibagentClient, LockStepMoveSameHashStartedBeforeOrAfterAndInProcess) {
  const int team = 94, player = 1;  // N = 1035: used by no other test
  const al::RobotNames names = al::simulationNames(team, player);
  const long ticks = 400;
  const Scenario ext = robotScenario(ticks / 100.0, team, player, "external");

  // Before: the program creates the (empty) objects and waits in sem_wait.
  RunStats before;
  double head_before = 0, knee_before = 0;
  {
    // Leftovers of an interrupted earlier run would make "before" untestable.
    for (const std::string& n : {names.memory, names.extension, names.images}) shm_unlink(n.c_str());
    sem_unlink(names.semaphore.c_str());
    const pid_t client = spawn(clientArgs(team, player, ticks));
    const auto t0 = Clock::now();
    while (!existsInShm(names.memory) && Clock::now() - t0 < std::chrono::seconds(10))
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_TRUE(existsInShm(names.memory)) << "the client did not create " << names.memory;
    Runner r(ext);
    try {
      before = r.run(quiet());
    } catch (...) {
      kill(client, SIGKILL);
      waitpid(client, nullptr, 0);
      throw;
    }
    EXPECT_EQ(waitExit(client, 10), 0);
    head_before = modelJoint(r, "HeadYaw");
    knee_before = modelJoint(r, "LKneePitch");
  }
  // After: the simulator has set the objects up when the program starts.
  RunStats after;
  {
    Runner r(ext);
    r.start();
    ASSERT_TRUE(existsInShm(names.memory));
    const pid_t client = spawn(clientArgs(team, player, ticks));
    try {
      after = r.run(quiet());
    } catch (...) {
      kill(client, SIGKILL);
      waitpid(client, nullptr, 0);
      throw;
    }
    EXPECT_EQ(waitExit(client, 10), 0);
  }
  // In-process: the robot program in the simulator's process, same moves.
  RunStats inproc;
  {
    Runner r(robotScenario(ticks / 100.0, team, player, "builtin"));
    r.programs().setMotionGenerator(0, std::make_unique<SameMoves>());
    inproc = r.run(quiet());
  }
  EXPECT_EQ(before.ticks, ticks);
  EXPECT_EQ(before.hash, after.hash);
  EXPECT_EQ(before.hash, inproc.hash);
  EXPECT_EQ(before.skipped_cycles, 0);
  EXPECT_EQ(before.falls, 0);
  // The moves happened: head turned 0.5 rad (standing posture: 0), knees back.
  EXPECT_NEAR(head_before, 0.5, 0.05);
  EXPECT_NEAR(knee_before, 0.8, 0.1);
  EXPECT_FALSE(existsInShm(names.memory)) << "the simulator removes its objects";
}

// The knee bend in the middle of the script is seen by the simulated body
// while it happens (a command written at tick k drives tick k + 1).
TEST(LibagentClient, LegMoveReachesTheBody) {
  const int team = 94, player = 4;
  Runner r(robotScenario(2.5, team, player, "external"));
  r.start();
  const pid_t client = spawn(clientArgs(team, player, 250));
  double knee_max = 0;
  try {
    while (r.ticks() < 250) {
      r.tick();
      knee_max = std::max(knee_max, modelJoint(r, "LKneePitch"));
    }
  } catch (...) {
    kill(client, SIGKILL);
    waitpid(client, nullptr, 0);
    throw;
  }
  r.shutdown();
  EXPECT_EQ(waitExit(client, 10), 0);
  EXPECT_NEAR(knee_max, 0.8 + 0.4, 0.08);  // stand 0.8 rad + 2 x 0.2 rad
}

// Through the raw 2017 block, a standing robot's eight FSRs sum to its mass
// in kg (the NAO's unit), within 5 %.
TEST(LibagentClient, StandingRobotsFsrsSumToItsMassInKg) {
  const int team = 94, player = 2;
  Runner r(robotScenario(2.0, team, player, "external"));
  r.start();
  const std::string out = tmpPath("fsr.txt");
  const pid_t client = spawn(clientArgs(team, player, 200, {"--hold", "--print-fsr"}), out);
  try {
    r.run(quiet());
  } catch (...) {
    kill(client, SIGKILL);
    waitpid(client, nullptr, 0);
    throw;
  }
  ASSERT_EQ(waitExit(client, 10), 0);
  const std::string text = slurp(out);
  std::remove(out.c_str());
  const size_t at = text.find("fsr-sum-kg ");
  ASSERT_NE(at, std::string::npos) << text;
  const double sum = std::stod(text.substr(at + 11));
  const double mass = r.world().robot(0).model().totalMass();
  std::printf("FSR sum %.3f kg, model mass %.3f kg (%.2f %%)\n", sum, mass, 100 * (sum - mass) / mass);
  EXPECT_NEAR(sum, mass, 0.05 * mass);
  EXPECT_GT(mass, 4.5);  // a NAO: about 5.3 kg
}

// Free-running (--realtime): the program sleeps 600 ms; the simulator keeps
// its pace, counts the skipped cycles and, after more than 50, sits the body down.
TEST(LibagentClient, FreeRunningClientThatSleepsIsSatDownAndSkipsAreCounted) {
  const int team = 94, player = 5;
  Runner r(robotScenario(2.0, team, player, "external"));
  r.setFreeRunning(true);
  r.start();
  const pid_t client = spawn(clientArgs(team, player, 100000, {"--hold", "--sleep-at", "50", "600", "--timeout", "2"}));
  bool lost = false;
  double knee_start = 0, knee_max = 0;
  std::string summary;
  try {
    r.tick();  // waits for the program's first answer (attach)
    knee_start = modelJoint(r, "LKneePitch");
    const auto wall0 = Clock::now();
    while (r.ticks() < 200) {
      r.tick();
      lost = lost || r.host(0).contactLost();
      knee_max = std::max(knee_max, modelJoint(r, "LKneePitch"));
      std::this_thread::sleep_until(wall0 + std::chrono::microseconds((r.ticks() - 1) * 10000));
    }
    summary = r.stats().summary();
  } catch (...) {
    kill(client, SIGKILL);
    waitpid(client, nullptr, 0);
    throw;
  }
  r.shutdown();
  waitExit(client, 5);
  std::printf("skipped %lld cycles, knee %.3f -> max %.3f rad; %s\n",
              static_cast<long long>(r.host(0).skippedCycles()), knee_start, knee_max, summary.c_str());
  EXPECT_TRUE(lost);
  EXPECT_GE(r.host(0).skippedCycles(), 50);
  EXPECT_EQ(r.host(0).contactLostEvents(), 1);
  EXPECT_NE(summary.find("skipped "), std::string::npos) << summary;
  // Sitting: the knees bend well past the standing 0.8 rad toward libagent's sit (125 deg).
  EXPECT_GT(knee_max, knee_start + 0.3);
}

// The program stops answering (here: it exits after 100 ticks): the watchdog
// names the robot instead of hanging.
TEST(LibagentClient, WatchdogNamesASilentExternalRobot) {
  const int team = 96, player = 1;
  Scenario s = robotScenario(3.0, team, player, "external");
  s.watchdog_s = 1.0;
  Runner r(s);
  r.start();
  const pid_t client = spawn(clientArgs(team, player, 100, {"--hold"}));
  std::string message;
  try {
    r.run(quiet());
  } catch (const simswift::runner::WatchdogError& e) {
    message = e.what();
  }
  EXPECT_EQ(waitExit(client, 10), 0);
  EXPECT_NE(message.find("robot t96p1: motion thread did not answer within 1 s (tick 101"), std::string::npos)
      << message;
}

// simswift killed with SIGKILL: the attached simswift-agent notices within
// 2 s and exits with a message; the next run for the robot starts cleanly
// on the stale objects.
TEST(SimswiftAgent, OutlivesAKilledSimulatorByLessThanTwoSecondsAndTheNextRunStartsCleanly) {
  const int team = 94, player = 3;
  const al::RobotNames names = al::simulationNames(team, player);
  const std::string yaml = tmpPath("kill.yaml"), sim_err = tmpPath("sim.err"), agent_err = tmpPath("agent.err");
  {
    std::ofstream f(yaml);
    f << "duration: 120\nattach_timeout: 20\nrobots:\n  - {team: 94, player: 3, program: external}\n";
  }
  const pid_t sim = spawn({kBin + "/simswift", "run", yaml, "--quiet"}, "", sim_err);
  const pid_t agent = spawn({kBin + "/simswift-agent", "--team", "94", "--player", "3", "--attach-timeout", "20"},
                            "", agent_err);
  // Wait until the robot runs: the agent announced and ticks advance.
  bool running = false;
  const auto t0 = Clock::now();
  while (!running && Clock::now() - t0 < std::chrono::seconds(20)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const int fd = shm_open(names.extension.c_str(), O_RDONLY, 0);
    if (fd < 0) continue;
    struct stat st {};
    if (fstat(fd, &st) == 0 && static_cast<size_t>(st.st_size) >= sizeof(al::SimExtension)) {
      void* p = mmap(nullptr, sizeof(al::SimExtension), PROT_READ, MAP_SHARED, fd, 0);
      if (p != MAP_FAILED) {
        const auto* x = static_cast<const al::SimExtension*>(p);
        running = x->client_pid.load() != 0 && x->slot_tick[0] + x->slot_tick[1] + x->slot_tick[2] > 60;
        munmap(p, sizeof(al::SimExtension));
      }
    }
    close(fd);
  }
  if (!running) {
    kill(sim, SIGKILL);
    kill(agent, SIGKILL);
  }
  ASSERT_TRUE(running) << slurp(sim_err) << slurp(agent_err);
  kill(sim, SIGKILL);
  waitpid(sim, nullptr, 0);
  double took = 0;
  const int status = waitExit(agent, 5, &took);
  const std::string agent_text = slurp(agent_err);
  std::printf("simswift-agent exited %.2f s after the simulator was killed: %s", took, agent_text.c_str());
  EXPECT_EQ(status, 1);
  EXPECT_LT(took, 2.0);
  EXPECT_NE(agent_text.find("simulator is gone"), std::string::npos) << agent_text;

  // The next run: takes the stale objects over (SIGKILL cleaned nothing;
  // unless a run in parallel swept them already) and runs with a new program.
  {
    Runner r(robotScenario(0.5, team, player, "external"));
    r.start();
    const pid_t next = spawn({kBin + "/simswift-agent", "--team", "94", "--player", "3"});
    RunStats st;
    try {
      st = r.run(quiet());
    } catch (...) {
      kill(next, SIGKILL);
      waitpid(next, nullptr, 0);
      throw;
    }
    EXPECT_EQ(waitExit(next, 10), 0);
    EXPECT_EQ(st.ticks, 50);
  }
  EXPECT_FALSE(existsInShm(names.memory));
  for (const std::string& f : {yaml, sim_err, agent_err}) std::remove(f.c_str());
}

// A robot program in another process (simswift-agent) gets the game state
// and a team link as a builtin one does: penalised at 1 s, it reads the
// penalty by 2 s; it and its builtin teammate hear each other's 5 Hz packets.
TEST(SimswiftAgent, ExternalProgramReadsTheGameStateAndTalksToItsTeammate) {
  const int team = 97;  // players 1 (external) and 2 (builtin): used by no other test
  Runner r(Scenario::parse("duration: 3\nseed: 5\nattach_timeout: 20\nwatchdog: 10\n"
                           "game: {penalties: [{t: 1, robot: 0, penalty: player_pushing, duration: 20}]}\n"
                           "robots:\n  - {team: 97, player: 1, x: -1.0, program: external}\n"
                           "  - {team: 97, player: 2, x: -2.0, y: 1.0}\n",
                           "external_team.yaml"));
  r.start();
  const std::string out = tmpPath("agent-game.txt");
  const pid_t agent = spawn({kBin + "/simswift-agent", "--team", std::to_string(team), "--player", "1", "--print",
                             "--attach-timeout", "20"},
                            out);
  try {
    r.run(quiet());
  } catch (...) {
    kill(agent, SIGKILL);
    waitpid(agent, nullptr, 0);
    throw;
  }
  ASSERT_EQ(waitExit(agent, 10), 0);
  const std::string text = slurp(out);
  std::remove(out.c_str());
  // Printed at 1 s, 2 s and 3 s of simulated time.
  EXPECT_NE(text.find("game: known 1 state PLAYING penalised 0"), std::string::npos) << text;
  const size_t at2 = text.find("t 2.00 s");
  ASSERT_NE(at2, std::string::npos) << text;
  const size_t g2 = text.find("game: ", at2);
  ASSERT_NE(g2, std::string::npos) << text;
  const std::string line = text.substr(g2, text.find('\n', g2) - g2);
  EXPECT_NE(line.find("penalised 1"), std::string::npos) << line;
  long long received = -1, malformed = -1;
  ASSERT_EQ(std::sscanf(line.substr(line.find("team:")).c_str(), "team: received %lld malformed %lld", &received,
                        &malformed),
            2)
      << line;
  EXPECT_EQ(malformed, 0);
  EXPECT_GE(received, 5);  // the builtin teammate's packets (5 Hz for 2 s)
  const agent::blackboard::TeamInfo mate = r.programs().program(1)->board().team.read();
  EXPECT_TRUE(mate.mates[1].valid) << "the builtin teammate heard nothing from the external player";
  EXPECT_GE(mate.received, 10);  // the external player's, 5 Hz for 3 s
}

// The game state and the team link an external program reads are in the
// robot's named extension object, the same memory the runner fills.
TEST(LibagentClient, GameStateIsInTheNamedExtensionObject) {
  const int team = 96, player = 2;
  const al::RobotNames names = al::simulationNames(team, player);
  Runner r(robotScenario(1.0, team, player, "external"));
  r.start();  // fills the game state for t = 0
  const int fd = shm_open(names.extension.c_str(), O_RDONLY, 0);
  ASSERT_GE(fd, 0);
  void* p = mmap(nullptr, sizeof(al::SimExtension), PROT_READ, MAP_SHARED, fd, 0);
  close(fd);
  ASSERT_NE(p, MAP_FAILED);
  const auto* x = static_cast<const al::SimExtension*>(p);
  EXPECT_EQ(x->magic, al::kExtensionMagic);
  EXPECT_GE(x->game.updates, 1u);
  EXPECT_EQ(x->game.updates, r.extensions(0)->game.updates);
  EXPECT_EQ(x->game.teams[0].team_number, 96);  // the blue side's SPL number
  EXPECT_EQ(x->team.magic, al::kTeamLinkMagic);
  munmap(p, sizeof(al::SimExtension));
}

TEST(ScenarioTeams, SplTeamNumbersAndColours) {
  const Scenario s = Scenario::parse(
      "robots:\n"
      "  - {team: 19, player: 1, x: -1}\n"
      "  - {team: 5, player: 1, x: 1}\n"
      "  - {team: 19, player: 2, x: -2, names: bare}\n",
      "teams.yaml");
  EXPECT_EQ(s.robots[0].team, 19);
  EXPECT_EQ(s.robots[0].colour, TeamColour::Blue);  // first team number: blue
  EXPECT_EQ(s.robots[1].colour, TeamColour::Red);   // second: red
  EXPECT_EQ(s.robots[2].colour, TeamColour::Blue);  // a team keeps its colour
  EXPECT_TRUE(s.robots[2].bare_names);
  const Scenario red_first = Scenario::parse(
      "robots:\n  - {team: 19, player: 1, x: -1, colour: red}\n  - {team: 5, player: 1, x: 1}\n", "teams.yaml");
  EXPECT_EQ(red_first.robots[1].colour, TeamColour::Blue);

  auto error = [](const std::string& text) {
    try {
      Scenario::parse(text, "teams.yaml");
    } catch (const simswift::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string third =
      error("robots:\n  - {team: 19, player: 1}\n  - {team: 5, player: 1}\n  - {team: 7, player: 1}\n");
  EXPECT_NE(third.find("teams.yaml:4: robots[2].team: a match has two teams (19 and 5)"), std::string::npos) << third;
  const std::string clash =
      error("robots:\n  - {team: 19, player: 1}\n  - {team: 5, player: 1, colour: blue}\n");
  EXPECT_NE(clash.find("robots[1].colour: team 19 already plays in blue"), std::string::npos) << clash;
  const std::string two_bare =
      error("robots:\n  - {team: 19, player: 1, names: bare}\n  - {team: 19, player: 2, names: bare}\n");
  EXPECT_NE(two_bare.find("robots[1].names: only one robot"), std::string::npos) << two_bare;
}

// ---- libagent's releases and behaviour through unchanged clients.

namespace {

Scenario releaseScenario(double duration, int team, int player, const std::string& libagent,
                         const std::string& actions = "") {
  return Scenario::parse("duration: " + std::to_string(duration) +
                             "\nseed: 3\nattach_timeout: 20\nwatchdog: 10\nrobots:\n  - {team: " +
                             std::to_string(team) + ", player: " + std::to_string(player) +
                             ", x: -1.0, program: external, libagent: " + libagent +
                             (actions.empty() ? "" : ", actions: " + actions) + "}\n",
                         "release.yaml");
}

std::vector<std::string> releaseClient(int release, int team, int player, long ticks,
                                       std::vector<std::string> extra = {}) {
  std::vector<std::string> a = clientArgs(team, player, ticks, std::move(extra));
  a[0] = kBin + "/libagent" + std::to_string(release) + "-client";
  return a;
}

// Runs `r` to its end with `client` attached; the client's stdout.
std::string runWith(Runner& r, pid_t client, const std::string& out) {
  try {
    r.run(quiet());
  } catch (...) {
    kill(client, SIGKILL);
    waitpid(client, nullptr, 0);
    throw;
  }
  EXPECT_EQ(waitExit(client, 10), 0);
  const std::string text = slurp(out);
  std::remove(out.c_str());
  return text;
}

double fsrSum(const std::string& text) {
  const size_t at = text.find("fsr-sum-kg ");
  return at == std::string::npos ? -1 : std::stod(text.substr(at + 11));
}

// rUNSWift 2016's libagent has one pair of names (/libagent-memory,
// /libagent-semaphore, no team or player in them): tests that run a 2016
// robot hold this lock for their whole run, so ctest -j runs them one at a
// time (each test is its own process).
class Bare2016NamesLock {
 public:
  Bare2016NamesLock() : fd_(::open("/tmp/simswift-test-libagent2016.lock", O_RDWR | O_CREAT | O_CLOEXEC, 0666)) {
    if (fd_ >= 0) ::flock(fd_, LOCK_EX);
  }
  ~Bare2016NamesLock() {
    if (fd_ >= 0) ::close(fd_);
  }
  Bare2016NamesLock(const Bare2016NamesLock&) = delete;
  Bare2016NamesLock& operator=(const Bare2016NamesLock&) = delete;

 private:
  int fd_;
};

}  // namespace

// Each release's client (its own block and names) attaches, runs in
// lock-step and reads a standing robot's mass on the FSRs within 2 %:
// 2017 and 2018 started before or after the simulator; 2016, which opens
// the objects without O_CREAT, after it (started before, it says why it
// cannot attach, as on a NAO before libagent is loaded).
TEST(LibagentReleases, EachReleasesClientAttachesInLockStepAndReadsTheMass) {
  const Bare2016NamesLock bare_names;
  const int team = 71, player = 3;
  for (int release : {2016, 2017, 2018}) {
    for (bool client_first : {false, true}) {
      SCOPED_TRACE("release " + std::to_string(release) + (client_first ? ", client first" : ", simulator first"));
      const std::string out = tmpPath("release.txt");
      if (client_first && release == 2016) {
        const std::string err = tmpPath("release-err.txt");
        const pid_t early = spawn(releaseClient(release, team, player, 10, {"--hold"}), out, err);
        EXPECT_EQ(waitExit(early, 10), 4);
        EXPECT_NE(slurp(err).find("must be up before a 2016 robot program starts"), std::string::npos) << slurp(err);
        std::remove(err.c_str());
        continue;
      }
      Runner r(releaseScenario(2.0, team, player, "{release: " + std::to_string(release) + "}"));
      pid_t client = -1;
      if (client_first) client = spawn(releaseClient(release, team, player, 200, {"--hold", "--print-fsr"}), out);
      r.start();
      EXPECT_EQ(r.host(0).memoryName(), release == 2016   ? std::string("/libagent-memory")
                                        : release == 2018 ? "/libagent-memory" + std::to_string(team * 6 + player)
                                                          : "/libagent-memory" + std::to_string(team * 11 + player));
      if (!client_first) client = spawn(releaseClient(release, team, player, 200, {"--hold", "--print-fsr"}), out);
      const double sum = fsrSum(runWith(r, client, out));
      const double mass = r.world().robot(0).model().totalMass();
      std::printf("release %d: FSR sum %.3f kg, model %.3f kg\n", release, sum, mass);
      EXPECT_NEAR(sum, mass, 0.02 * mass);
    }
  }
}

// start: stiff (default): `standing` from attach until the program's first
// command (its Effector clears it), then never again.
TEST(LibagentReleases, StandingIsSetUntilTheFirstCommand) {
  const int team = 72, player = 1;
  Runner r(releaseScenario(0.5, team, player, "{start: stiff}"));
  r.start();
  const std::string out = tmpPath("standing.txt");
  const pid_t client = spawn(releaseClient(2017, team, player, 50, {"--hold", "--print-standing"}), out);
  const std::string text = runWith(r, client, out);
  EXPECT_NE(text.find("standing 1 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("standing 2 0\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("standing 3 1"), std::string::npos) << text;
}

// start: limp: the joints read stiffness 0 and the torso sinks until the
// program sends STIFFEN; then `standing` once, and the body holds the
// program's command.
TEST(LibagentReleases, LimpStartSinksUntilStiffenThenStandingOnceAndTheCommandHolds) {
  const int team = 72, player = 2;
  Runner r(releaseScenario(3.0, team, player, "{start: limp}"));
  r.start();
  const std::string out = tmpPath("limp.txt");
  const long stiffen_at = 150;
  const pid_t client =
      spawn(releaseClient(2017, team, player, 300, {"--stand", "--print-standing", "--stiffen-at", std::to_string(stiffen_at)}), out);
  const simswift::RobotBody& body = r.world().robot(0);
  auto torsoZ = [&] { return body.linkPose(body.model().rootLink()).translation().z(); };
  double z0 = 0, z_before = 0;
  float stiffness_read_max = 0;
  try {
    while (r.ticks() < 300) {
      r.tick();
      if (r.ticks() == 1) z0 = torsoZ();
      const al::AgentData& b = *r.host(0).block();
      if (r.ticks() < stiffen_at)
        for (float st : b.sensors[al::loadIndex(b.sensors_latest)].joints.stiffnesses)
          stiffness_read_max = std::max(stiffness_read_max, st);
      if (r.ticks() == stiffen_at) z_before = torsoZ();
    }
  } catch (...) {
    kill(client, SIGKILL);
    waitpid(client, nullptr, 0);
    throw;
  }
  r.shutdown();
  EXPECT_EQ(waitExit(client, 10), 0);
  const std::string text = slurp(out);
  std::remove(out.c_str());
  std::printf("torso %.3f m at start, %.3f m before STIFFEN; knees %.3f rad at the end\n", z0, z_before,
              modelJoint(r, "LKneePitch"));
  EXPECT_EQ(stiffness_read_max, 0.0f);
  EXPECT_LT(z_before, z0 - 0.03);  // the limp body sags
  // STIFFEN with tick 150's command: `standing` read on the next tick, cleared after.
  EXPECT_NE(text.find("standing " + std::to_string(stiffen_at + 1) + " 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("standing " + std::to_string(stiffen_at + 2) + " 0\n"), std::string::npos) << text;
  EXPECT_FALSE(r.host(0).libagent().limp());
  EXPECT_NEAR(modelJoint(r, "LKneePitch"), 0.8, 0.1);  // the program's stand holds
}

// Clicks from the scenario: one chest click reaches ButtonPresses (bit 0)
// exactly once; a double click makes the body limp and a second one stiff
// again, with `standing`; head touches never reach ButtonPresses.
TEST(LibagentReleases, ScenarioClicksAreCountedAsLibagentCountsThem) {
  const int team = 72, player = 3;
  Runner r(releaseScenario(4.0, team, player, "{start: stiff}",
                           "[{t: 0.2, click: chest}, {t: 1.0, click: chest, count: 2}, "
                           "{t: 2.0, click: chest, count: 2}, {t: 3.0, press: head_front, for: 0.3}]"));
  r.start();
  const std::string out = tmpPath("clicks.txt");
  const pid_t client = spawn(releaseClient(2017, team, player, 400, {"--stand", "--print-standing"}), out);
  int single = 0, other = 0;
  double single_at = -1;
  bool limp_seen = false;
  try {
    while (r.ticks() < 400) {
      r.tick();
      const al::AgentData& b = *r.host(0).block();
      const al::ButtonPresses p = b.buttons[al::loadIndex(b.sensors_latest)];
      if (p == al::Buttons::kSingleClick) {
        ++single;
        single_at = r.world().time();
      } else if (p != 0) {
        ++other;
      }
      if (r.world().time() > 1.5 && r.world().time() < 2.0) limp_seen = limp_seen || r.host(0).libagent().limp();
    }
  } catch (...) {
    kill(client, SIGKILL);
    waitpid(client, nullptr, 0);
    throw;
  }
  r.shutdown();
  EXPECT_EQ(waitExit(client, 10), 0);
  const std::string text = slurp(out);
  std::remove(out.c_str());
  EXPECT_EQ(single, 1);
  EXPECT_EQ(other, 0);
  // Pressed 0.2-0.3 s; up from the tick at 0.3 s; out after more than 18 cycles up.
  EXPECT_NEAR(single_at, 0.3 + 0.19, 0.011);
  EXPECT_TRUE(limp_seen);
  // The second double click sets `standing` once (the client read it on one tick).
  size_t sets = 0;
  for (size_t at = text.find(" 1\n"); at != std::string::npos; at = text.find(" 1\n", at + 1)) ++sets;
  EXPECT_EQ(sets, 2u) << text;  // tick 1 (the start's) and the one after the stiffening clicks
  EXPECT_FALSE(r.host(0).libagent().limp());
}

// The end of a run: an unchanged program still attached is not woken (it
// would re-read the last sensor slot as a new cycle) and is named, pid and
// all, so the user can stop it before the next run.
TEST(LibagentReleases, AtTheEndAnUnchangedProgramIsNotWokenAndIsNamed) {
  const int team = 72, player = 4;
  Runner r(releaseScenario(0.3, team, player, "{start: stiff}"));
  r.start();
  const pid_t client = spawn(releaseClient(2017, team, player, 100000, {"--hold"}));
  testing::internal::CaptureStderr();
  try {
    r.run(quiet());
  } catch (...) {
    testing::internal::GetCapturedStderr();
    kill(client, SIGKILL);
    waitpid(client, nullptr, 0);
    throw;
  }
  const std::string err = testing::internal::GetCapturedStderr();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(r.host(0).answered()) << "the program answered a cycle after the end";
  EXPECT_EQ(waitExit(client, 0.2), -1) << "it waits (and is killed here)";
  EXPECT_NE(err.find("(pid " + std::to_string(client) + ") is still attached"), std::string::npos) << err;
}

// Each release's libagent behaviour through that release's own client
// (rUNSWift 2016 and 2018; 2017 is above). Limp start: the body gets the
// release's sit pose at stiffness 0; the client's STIFFEN at tick 100
// stiffens a 2018 body (`standing` read once, on tick 101) and does nothing
// to a 2016 body (its block has no stiffen[]: the 2016 client cannot send
// one), which a double chest click at 1.5 s stiffens instead, `standing`
// once. Either way the client's stand holds afterwards.
TEST(LibagentReleases, Release2016And2018LimpStartStiffenAndStandingThroughTheirOwnClients) {
  const Bare2016NamesLock bare_names;
  namespace J = al::Joints;
  using LB = simswift::bridge::LibagentBehaviour;
  for (int release : {2016, 2018}) {
    SCOPED_TRACE("release " + std::to_string(release));
    const int team = 73, player = release == 2016 ? 1 : 2;
    Runner r(releaseScenario(3.0, team, player, "{start: limp, release: " + std::to_string(release) + "}",
                             release == 2016 ? "[{t: 1.5, click: chest, count: 2}]" : ""));
    r.start();
    const auto rel = static_cast<simswift::bridge::Release>(release);
    const std::string out = tmpPath("limp-" + std::to_string(release) + ".txt");
    const pid_t client =
        spawn(releaseClient(release, team, player, 300, {"--stand", "--print-standing", "--stiffen-at", "100"}), out);
    bool limp_sit_held = true;
    bool limp_at_120 = false;
    try {
      while (r.ticks() < 300) {
        r.tick();
        if (r.ticks() == 120) limp_at_120 = r.host(0).libagent().limp();
        if (r.ticks() < 100) {
          const al::JointValues& j = r.lastCommand(0).joints;
          for (int q = 0; q < al::kNumJoints; ++q)
            limp_sit_held = limp_sit_held && j.stiffnesses[q] == 0.0f && j.angles[q] == LB::sitAngles(rel)[q];
        }
      }
    } catch (...) {
      kill(client, SIGKILL);
      waitpid(client, nullptr, 0);
      throw;
    }
    r.shutdown();
    EXPECT_EQ(waitExit(client, 10), 0);
    const std::string text = slurp(out);
    std::remove(out.c_str());
    EXPECT_TRUE(limp_sit_held);
    EXPECT_NE(text.find("standing 1 0\n"), std::string::npos) << text;  // limp: not yet
    size_t sets = 0;
    for (size_t at = text.find(" 1\n"); at != std::string::npos; at = text.find(" 1\n", at + 1)) ++sets;
    EXPECT_EQ(sets, 1u) << text;
    if (release == 2018) {
      EXPECT_NE(text.find("standing 101 1\nstanding 102 0\n"), std::string::npos) << text;
      EXPECT_FALSE(limp_at_120);
    } else {
      EXPECT_TRUE(limp_at_120);  // the STIFFEN the 2016 block cannot carry
      EXPECT_EQ(text.find("standing 101 1"), std::string::npos) << text;
    }
    EXPECT_FALSE(r.host(0).libagent().limp());
    EXPECT_EQ(r.lastCommand(0).joints.stiffnesses[J::LKneePitch], 1.0f);
    EXPECT_NEAR(r.lastCommand(0).joints.angles[J::LKneePitch], 0.8f, 1e-6);  // the client's stand
  }
}

// Stiff start, then the client stops answering (it exits after 100 ticks)
// in free-running mode: `standing` until its first command, then contact
// lost after more than 50 skipped cycles and the release's own sit:
// 2016 straight to its pose at stiffness 1 (arms there in 100 cycles, the
// rest in 200); 2018 via the middle pose (200 cycles at 1, 100 at 0.2).
TEST(LibagentReleases, Release2016And2018StandingThenTheirOwnSitAfterContactLoss) {
  const Bare2016NamesLock bare_names;
  namespace J = al::Joints;
  using LB = simswift::bridge::LibagentBehaviour;
  for (int release : {2016, 2018}) {
    SCOPED_TRACE("release " + std::to_string(release));
    const int team = 73, player = release == 2016 ? 3 : 4;
    Runner r(releaseScenario(6.0, team, player, "{start: stiff, release: " + std::to_string(release) + "}"));
    r.start();
    const auto rel = static_cast<simswift::bridge::Release>(release);
    const std::string out = tmpPath("sit-" + std::to_string(release) + ".txt");
    const pid_t client = spawn(releaseClient(release, team, player, 100, {"--stand", "--print-standing"}), out);
    std::vector<al::JointValues> sit;  // the body's command from the first sit cycle on
    try {
      while (r.ticks() < 100) r.tick();
      EXPECT_EQ(waitExit(client, 10), 0);  // answered its 100 ticks and left
      r.setFreeRunning(true);
      while (r.ticks() < 500) {
        r.tick();
        if (r.host(0).contactLost()) sit.push_back(r.lastCommand(0).joints);
      }
    } catch (...) {
      kill(client, SIGKILL);
      waitpid(client, nullptr, 0);
      throw;
    }
    r.shutdown();
    const std::string text = slurp(out);
    std::remove(out.c_str());
    EXPECT_NE(text.find("standing 1 1\nstanding 2 0\n"), std::string::npos) << text;
    EXPECT_EQ(r.host(0).contactLostEvents(), 1);
    ASSERT_GE(sit.size(), 302u);
    const auto& pose = LB::sitAngles(rel);
    if (release == 2016) {
      for (int n = 1; n <= 200; ++n) ASSERT_EQ(sit[n - 1].stiffnesses[J::LKneePitch], 1.0f) << n;
      EXPECT_NEAR(sit[99].angles[J::LElbowYaw], pose[J::LElbowYaw], 1e-5);  // arms there at 100
      EXPECT_NEAR(sit[99].angles[J::LKneePitch], 0.5f * (0.8f + pose[J::LKneePitch]), 0.02);  // legs half way
      EXPECT_NEAR(sit[199].angles[J::LKneePitch], pose[J::LKneePitch], 1e-5);
      EXPECT_EQ(sit[200].stiffnesses[J::LKneePitch], 0.0f);  // then limp
    } else {
      const auto& middle = *LB::sitMiddleAngles(rel);
      EXPECT_NEAR(sit[199].angles[J::LElbowYaw], middle[J::LElbowYaw], 1e-5);
      EXPECT_EQ(sit[199].stiffnesses[J::LKneePitch], 1.0f);
      EXPECT_EQ(sit[200].stiffnesses[J::LKneePitch], 0.2f);
      EXPECT_NEAR(sit[299].angles[J::LElbowYaw], pose[J::LElbowYaw], 1e-5);
      EXPECT_EQ(sit[300].stiffnesses[J::LKneePitch], 0.0f);
    }
    EXPECT_TRUE(r.host(0).libagent().limp());
    std::printf("release %d: knee %.3f rad after the sit (its pose %.3f), falls %d\n", release,
                modelJoint(r, "LKneePitch"), pose[J::LKneePitch], r.robotFall(0).falls);
  }
}
