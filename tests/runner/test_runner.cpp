// The lock-step runner: determinism, external robot processes, the watchdog,
// command latency and fall counting.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"
#include "tests/runner/RunnerTestUtil.hpp"

namespace al = common::libagent;
namespace ap = agent::program;
using simswift::runner::RunOptions;
using simswift::runner::Runner;
using simswift::runner::RunStats;
using simswift::runner::Scenario;
using simswift::runner::WatchdogError;

namespace {

Scenario oneRobot(double duration, const std::string& extra = "") {
  return Scenario::parse("duration: " + std::to_string(duration) +
                             "\nrobots:\n  - {team: 0, player: 1, x: -1.0, y: 0.0, theta: 0.0" + extra + "}\n",
                         "test.yaml");
}

using runnertest::quiet;

double modelJoint(Runner& r, int robot, const char* name) {
  const simswift::RobotBody& body = r.world().robot(robot);
  return body.jointAngle(body.model().jointIndex(name));
}

}  // namespace

// Same seed => same state hash, whatever the thread timing; another seed
// (noise on, fed back through the standing program's ankle damping) => another.
TEST(Runner, SameSeedSameHashOtherSeedOtherHash) {
  Scenario s = oneRobot(20.0);
  s.noise.on = true;
  s.seed = 7;
  const RunStats a = Runner(s).run(quiet());
  const RunStats b = Runner(s).run(quiet());
  s.seed = 8;
  const RunStats c = Runner(s).run(quiet());
  EXPECT_DOUBLE_EQ(a.sim_s, 20.0);
  EXPECT_EQ(a.ticks, 2000);
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_NE(a.hash, c.hash);
  EXPECT_EQ(a.falls, 0);  // standing robot stays up
  EXPECT_EQ(a.blowups, 0);
  EXPECT_EQ(a.nan_commands, 0);
}

// A command written during tick k drives the servos during tick k+1: a head
// move scripted at t = 0.5 s shows in the joint only after the tick that
// delivered it.
TEST(Runner, CommandsTakeEffectOnTheNextTickAndScriptsMoveJoints) {
  Scenario s = oneRobot(1.5, ", script: [{t: 0.5, joint: HeadYaw, angle: 0.6}]");
  s.noise.on = false;
  Runner r(s);
  r.start();
  while (r.ticks() < 50) r.tick();  // program saw t = 0.50 s, wrote 0.6 rad
  const double before = modelJoint(r, 0, "HeadYaw");
  EXPECT_NEAR(before, 0.0, 0.01);   // not applied yet during the tick that read it
  r.tick();                          // applied now
  EXPECT_GT(modelJoint(r, 0, "HeadYaw"), before + 0.01);
  while (r.ticks() < 150) r.tick();
  EXPECT_NEAR(modelJoint(r, 0, "HeadYaw"), 0.6, 0.05);
}

TEST(Runner, LimpRobotFallsOnceAndIsCounted) {
  Scenario s = oneRobot(2.0, ", posture: limp");
  const RunStats st = Runner(s).run(quiet());
  EXPECT_EQ(st.falls, 1);
}

namespace {
// A Motion step that stops answering at t >= 0.3 s until released.
struct HangingMotion : agent::framework::MotionGenerator {
  std::atomic<bool>* release;
  explicit HangingMotion(std::atomic<bool>* r) : release(r) {}
  void tick(const al::SensorValues&, int64_t t_us, al::JointValues& out) override {
    out = ap::postureCommand(ap::Posture::Stand);
    if (t_us < 300000) return;
    while (!release->load()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
};
}  // namespace

TEST(Runner, WatchdogNamesTheRobotAndThreadInsteadOfHanging) {
  Scenario s = Scenario::parse(
      "duration: 5\nwatchdog: 1\nrobots:\n  - {team: 1, player: 2, x: 1.0}\n", "test.yaml");
  std::atomic<bool> release{false};
  const auto t0 = std::chrono::steady_clock::now();
  std::string message;
  {
    Runner r(s);
    r.programs().setMotionGenerator(0, std::make_unique<HangingMotion>(&release));
    try {
      r.run(quiet());
    } catch (const WatchdogError& e) {
      message = e.what();
    }
    release = true;  // let the thread finish so the runner can join it
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_NE(message.find("robot t1p2: motion thread did not answer within 1 s (tick 30, sim 0.30 s)"),
            std::string::npos)
      << message;
  EXPECT_LT(wall, 4.0);
}

namespace {
// A Motion step that throws at t >= 0.3 s.
struct ThrowingMotion : agent::framework::MotionGenerator {
  void tick(const al::SensorValues&, int64_t t_us, al::JointValues& out) override {
    out = ap::postureCommand(ap::Posture::Stand);
    if (t_us >= 300000) throw std::runtime_error("walk engine exploded");
  }
};
}  // namespace

// Inline, a step that throws ends the run at once (no watchdog wait: there is
// no thread to wait for), naming the robot, the step and the program's error.
TEST(Runner, InlineStepThatThrowsEndsTheRunNamingTheRobot) {
  Scenario s = Scenario::parse("duration: 5\nwatchdog: 30\nrobots:\n  - {team: 1, player: 2, x: 1.0}\n", "test.yaml");
  Runner r(s);
  r.programs().setThreading(ap::Threading::Inline);
  r.programs().setMotionGenerator(0, std::make_unique<ThrowingMotion>());
  std::string message;
  try {
    r.run(quiet());
  } catch (const WatchdogError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("robot t1p2: motion step failed: t1p2-motion: walk engine exploded (tick 30)"),
            std::string::npos)
      << message;
  EXPECT_EQ(r.ticks(), 30);
}

// A second process attaches by name (simswift-agent), reads the sensors and
// moves a joint; the joint in the world follows.
TEST(Runner, ExternalProcessAttachesByNameAndMovesAJoint) {
  const std::string agent = std::string(SIMSWIFT_BINARY_DIR) + "/simswift-agent";
  ASSERT_EQ(access(agent.c_str(), X_OK), 0) << agent << " not built";
  Scenario s = Scenario::parse(
      "duration: 1.5\nattach_timeout: 20\nrobots:\n  - {team: 1, player: 4, x: 1.0, program: external}\n",
      "test.yaml");
  s.noise.on = false;
  Runner r(s);
  // The child may start before the block exists; it retries attaching.
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    execl(agent.c_str(), agent.c_str(), "--team", "1", "--player", "4", "--move", "HeadYaw", "-0.5", "--at", "0.2",
          "--attach-timeout", "20", static_cast<char*>(nullptr));
    _exit(127);
  }
  RunStats st;
  try {
    st = r.run(quiet());
  } catch (...) {
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
    throw;
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_NEAR(modelJoint(r, 0, "HeadYaw"), -0.5, 0.05);
  // It held the standing posture too: the knees stay bent at ~0.8 rad.
  EXPECT_NEAR(modelJoint(r, 0, "LKneePitch"), 0.8, 0.1);
  EXPECT_EQ(st.falls, 0);
}

// Fall attribution (FallDetector::contact_falls): a robot pushed over on its
// own counts a fall and no contact fall; a robot pushed into a standing
// teammate 0.35 m ahead brings one or both down, and every such fall counts
// as one after a robot contact. Impulse 6 N*s for the pair (about 1.1 m/s
// for the pushed 5.3 kg robot; 3 N*s, enough alone, leaves the pair leaning
// on each other).
TEST(Runner, FallsAfterTouchingAnotherRobotAreAttributed) {
  const std::string stand_push =
      ", actions: [{t: 0, action: stand}, {t: 0.5, push: {x: 3.0, y: 0.0}}]}\n";
  const std::string stand_shove =
      ", actions: [{t: 0, action: stand}, {t: 0.5, push: {x: 6.0, y: 0.0}}]}\n";
  {
    Scenario s = Scenario::parse("duration: 3.0\nrobots:\n  - {team: 0, player: 1, x: -1.0, y: 0.0, theta: 0.0" +
                                     stand_push,
                                 "alone.yaml");
    Runner r(s);
    const RunStats st = r.run(quiet());
    ASSERT_EQ(st.robots.size(), 1u);
    EXPECT_EQ(st.robots[0].falls, 1);
    EXPECT_EQ(st.robots[0].contact_falls, 0);
  }
  {
    Scenario s = Scenario::parse("duration: 3.0\nrobots:\n  - {team: 0, player: 1, x: -1.0, y: 0.0, theta: 0.0" +
                                     stand_shove +
                                     "  - {team: 0, player: 2, x: -0.65, y: 0.0, theta: 3.1416, actions: [{t: 0, action: stand}]}\n",
                                 "pair.yaml");
    Runner r(s);
    const RunStats st = r.run(quiet());
    ASSERT_EQ(st.robots.size(), 2u);
    std::printf("pushed into a teammate: falls %d / %d, after robot contact %d / %d\n", st.robots[0].falls,
                st.robots[1].falls, st.robots[0].contact_falls, st.robots[1].contact_falls);
    EXPECT_GE(st.robots[0].falls + st.robots[1].falls, 1);  // the two go down together (or one of them)
    for (int i = 0; i < 2; ++i) EXPECT_EQ(st.robots[i].contact_falls, st.robots[i].falls) << i;  // all after the contact
  }
}

// The scenario's `inertial:` reaches the robot's sensors: with acc_raw_sign
// -1 a standing robot's raw AccZ has the opposite sign of AccelerometerZ
// (same sign by default); the calibrated slot is the same either way.
TEST(Runner, InertialRawSignsReachTheSlots) {
  auto accZ = [](const std::string& inertial) {
    Scenario s = Scenario::parse(inertial + "duration: 1\nrobots:\n  - {team: 0, player: 1, x: -1.0}\n", "test.yaml");
    s.noise.on = false;
    Runner r(s);
    r.start();
    while (r.ticks() < 20) r.tick();
    const auto& v = r.sensors(0).reading().sensors;
    return std::make_pair(v[al::Sensors::InertialSensor_AccZ], v[al::Sensors::InertialSensor_AccelerometerZ]);
  };
  const auto same = accZ("");
  const auto flipped = accZ("inertial: {acc_raw_sign: -1}\n");
  // Upright: AccelerometerZ about -9.81 m/s^2 on the V5 (common/libagent/Inertial.hpp), raw about 65 counts per g.
  EXPECT_NEAR(same.second, -9.81, 0.5);
  EXPECT_NEAR(same.first, -65.0, 4.0);
  EXPECT_NEAR(flipped.first, 65.0, 4.0);
  EXPECT_FLOAT_EQ(flipped.second, same.second);
}
