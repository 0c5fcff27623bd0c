// The body side of libagent: round trips, skipped cycles and contact loss,
// and the named objects' permissions and lifetime.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <thread>

#include "agent/libagent/AgentConnection.hpp"
#include "sim/bridge/BodyHost.hpp"

namespace al = agent::libagent;
namespace ap = agent::program;
using simswift::bridge::BodyHost;
using simswift::bridge::BridgeError;

TEST(BodyHost, SensorsAndActuatorsRoundTrip) {
  BodyHost host(0, 3, BodyHost::Mode::InProcess);
  al::AgentConnection conn = host.connect();

  // Until the program writes, the body reads the initial (stand) command.
  EXPECT_EQ(host.readActuators().joints.angles[al::Joints::LKneePitch],
            ap::postureAngles(ap::Posture::Stand)[al::Joints::LKneePitch]);

  al::SensorValues v{};
  v.sensors[al::Sensors::InertialSensor_AccZ] = -9.81f;
  v.joints.angles[al::Joints::HeadPitch] = 0.125f;
  v.sonar[3] = 0.42f;
  EXPECT_TRUE(host.publishSensors(v, 250000, 25));

  ASSERT_TRUE(conn.waitTick());
  const al::SensorValues got = conn.readSensors();
  EXPECT_EQ(got.sensors[al::Sensors::InertialSensor_AccZ], -9.81f);
  EXPECT_EQ(got.joints.angles[al::Joints::HeadPitch], 0.125f);
  EXPECT_EQ(got.sonar[3], 0.42f);
  EXPECT_EQ(conn.simTimeUs(), 250000);
  EXPECT_EQ(conn.tick(), 25);

  al::ActuatorCommand cmd;
  cmd.joints.angles[al::Joints::LShoulderPitch] = 0.75f;
  cmd.joints.stiffnesses[al::Joints::LShoulderPitch] = 0.5f;
  cmd.sonar = 68.0f;
  cmd.stiffen = true;
  cmd.say = "ready";
  cmd.leds.chest[1] = 1.0f;
  conn.writeActuators(cmd);
  ASSERT_TRUE(host.waitMotionDone(1.0));
  const al::ActuatorCommand back = host.readActuators();
  EXPECT_EQ(back.joints.angles[al::Joints::LShoulderPitch], 0.75f);
  EXPECT_EQ(back.joints.stiffnesses[al::Joints::LShoulderPitch], 0.5f);
  EXPECT_EQ(back.sonar, 68.0f);
  EXPECT_TRUE(back.stiffen);
  EXPECT_EQ(back.say, "ready");
  EXPECT_EQ(back.leds.chest[1], 1.0f);
  EXPECT_EQ(host.skippedCycles(), 0);
}

TEST(BodyHost, WaitMotionDoneTimesOut) {
  BodyHost host(0, 2, BodyHost::Mode::InProcess);
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_FALSE(host.waitMotionDone(0.05));
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_GE(waited, 0.045);
  EXPECT_LT(waited, 2.0);
}

// A program that does not wait on the semaphore: the body posts once, then
// counts every cycle as skipped; after 50 in a row it sits the robot down,
// and recovers once the program takes a tick again.
TEST(BodyHost, CountsSkippedCyclesAndSitsDownWhenContactIsLost) {
  BodyHost host(1, 1, BodyHost::Mode::InProcess);
  al::AgentConnection conn = host.connect();
  al::SensorValues v{};
  EXPECT_TRUE(host.publishSensors(v, 10000, 1));
  for (int k = 2; k <= 50; ++k) EXPECT_FALSE(host.publishSensors(v, k * 10000, k));
  EXPECT_EQ(host.skippedCycles(), 49);
  EXPECT_EQ(host.block()->lockstep.skipped.load(), 49);
  EXPECT_FALSE(host.contactLost());
  EXPECT_FALSE(host.publishSensors(v, 510000, 51));
  EXPECT_TRUE(host.contactLost());  // 50 consecutive skipped cycles
  EXPECT_EQ(host.contactLostEvents(), 1);

  const al::ActuatorCommand sit = host.readActuators();
  const ap::JointArray crouch = ap::postureAngles(ap::Posture::Crouch);
  for (int j = 0; j < al::kNumJoints; ++j) {
    EXPECT_EQ(sit.joints.angles[j], crouch[j]);
    EXPECT_EQ(sit.joints.stiffnesses[j], ap::kSafeSitStiffness);
  }

  // The program takes its tick again: the next cycle posts and contact is back.
  ASSERT_TRUE(conn.waitTick());
  EXPECT_TRUE(host.publishSensors(v, 520000, 52));
  EXPECT_FALSE(host.contactLost());
  EXPECT_EQ(host.consecutiveSkipped(), 0);
}

namespace {
bool exists(const std::string& path, mode_t* mode = nullptr) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return false;
  if (mode) *mode = st.st_mode & 0777;
  return true;
}
}  // namespace

TEST(BodyHost, NamedObjectsAre0600AndRemovedOnDestruction) {
  // Team 1 player 5: suffix 11, used by no other test.
  const std::string shm_file = "/dev/shm/libagent-memory-11";
  const std::string sem_file = "/dev/shm/sem.libagent-semaphore-11";
  {
    BodyHost host(1, 5, BodyHost::Mode::Named);
    EXPECT_EQ(host.memoryName(), "/libagent-memory-11");
    mode_t mode = 0;
    ASSERT_TRUE(exists(shm_file, &mode));
    EXPECT_EQ(mode, 0600u);
    ASSERT_TRUE(exists(sem_file, &mode));
    EXPECT_EQ(mode & 0077u, 0u);  // no access for group/others (umask may only remove bits)

    // A second simulator for the same robot is refused with a clear message.
    try {
      BodyHost again(1, 5, BodyHost::Mode::Named);
      FAIL() << "second BodyHost for t1p5 was created";
    } catch (const BridgeError& e) {
      EXPECT_NE(std::string(e.what()).find("already exists"), std::string::npos) << e.what();
    }
    ASSERT_TRUE(exists(shm_file)) << "the failed second host removed the first one's object";

    // Attach by name (as another process would) and round-trip once.
    al::AgentConnection conn = al::AgentConnection::attachByName(1, 5);
    conn.announce(false);
    EXPECT_TRUE(host.attached());
    al::SensorValues v{};
    v.sensors[0] = 1.5f;
    host.publishSensors(v, 10000, 1);
    ASSERT_TRUE(conn.waitTick());
    EXPECT_EQ(conn.readSensors().sensors[0], 1.5f);
    al::JointValues j{};
    j.angles[al::Joints::HeadYaw] = -0.3f;
    conn.writeActuators(j);
    ASSERT_TRUE(host.waitMotionDone(1.0));
    EXPECT_EQ(host.readActuators().joints.angles[al::Joints::HeadYaw], -0.3f);
  }
  EXPECT_FALSE(exists(shm_file));
  EXPECT_FALSE(exists(sem_file));
}

TEST(BodyHost, RejectsRobotsOutsideTheTeamsAndPlayers) {
  EXPECT_THROW(BodyHost(2, 1, BodyHost::Mode::InProcess), BridgeError);
  EXPECT_THROW(BodyHost(0, 0, BodyHost::Mode::InProcess), BridgeError);
  EXPECT_THROW(BodyHost(0, 6, BodyHost::Mode::InProcess), BridgeError);
}

// A simulator killed by SIGTERM leaves nothing behind in /dev/shm.
TEST(BodyHost, NamedObjectsAreRemovedOnSigterm) {
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // Team 1 player 3: suffix 9, used by no other test.
    BodyHost host(1, 3, BodyHost::Mode::Named);
    raise(SIGTERM);
    _exit(0);  // not reached: SIGTERM's default action ends the process
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_FALSE(exists("/dev/shm/libagent-memory-9"));
  EXPECT_FALSE(exists("/dev/shm/sem.libagent-semaphore-9"));
}
