// The body side of libagent: round trips, lock-step answers detected from
// libagent's own protocol (including the Effector's slot-loop quirk),
// skipped cycles and contact loss, and the named objects' permissions,
// adoption, ownership and lifetime.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <semaphore.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <random>
#include <thread>
#include <vector>

#include "common/libagent/AgentConnection.hpp"
#include "common/libagent/TripleBuffer.hpp"
#include "sim/bridge/BodyHost.hpp"

namespace al = common::libagent;
namespace an = common::nao;  // the named postures (common/nao/Postures.hpp, via BodyHost.hpp)
namespace bridge = simswift::bridge;
using simswift::bridge::BodyHost;
using simswift::bridge::BridgeError;
using Clock = std::chrono::steady_clock;

TEST(BodyHost, SensorsAndActuatorsRoundTrip) {
  BodyHost host(19, 3, BodyHost::Mode::InProcess);
  al::AgentConnection conn = host.connect();

  // Until the program writes, the body reads the initial (stand) command.
  EXPECT_FALSE(host.answered());
  EXPECT_EQ(host.readActuators().joints.angles[al::Joints::LKneePitch],
            an::postureAngles(an::Posture::Stand)[al::Joints::LKneePitch]);

  al::SensorValues v{};
  v.sensors[al::Sensors::InertialSensor_AccZ] = -9.81f;
  v.sensors[al::Sensors::ChestBoard_Button] = 1.0f;
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
  EXPECT_EQ(conn.buttons(), 0);  // a press is no click until released (test_libagent_behaviour.cpp)

  al::ActuatorCommand cmd;
  cmd.joints.angles[al::Joints::LShoulderPitch] = 0.75f;
  cmd.joints.stiffnesses[al::Joints::LShoulderPitch] = 0.5f;
  cmd.sonar = 68.0f;
  cmd.stiffen = true;  // read back once; it also sets `standing` (libagent), so the body sits limp this cycle
  cmd.say = "ready";
  cmd.leds.chest.red = true;
  cmd.leds.right_ear = 0x155;
  conn.writeActuators(cmd);
  ASSERT_TRUE(host.waitAnswer(1.0));
  const al::ActuatorCommand back = host.readActuators();
  EXPECT_TRUE(host.standing());
  EXPECT_EQ(back.joints.stiffnesses[al::Joints::LShoulderPitch], 0.0f);
  cmd.stiffen = false;
  conn.writeActuators(cmd);  // clears `standing`, as libagent's Effector
  ASSERT_TRUE(host.waitAnswer(1.0));
  const al::ActuatorCommand obeyed = host.readActuators();
  EXPECT_EQ(obeyed.joints.angles[al::Joints::LShoulderPitch], 0.75f);
  EXPECT_EQ(obeyed.joints.stiffnesses[al::Joints::LShoulderPitch], 0.5f);
  EXPECT_EQ(back.sonar, 68.0f);
  EXPECT_TRUE(back.stiffen);
  EXPECT_EQ(back.say, "ready");
  EXPECT_TRUE(back.leds.chest.red);
  EXPECT_EQ(back.leds.right_ear, 0x155);
  // Consumed: actuators_latest is parked until the next answer.
  EXPECT_EQ(al::loadIndex(host.block()->actuators_latest), al::kActuatorsParked);
  EXPECT_FALSE(host.answered());
  EXPECT_EQ(host.skippedCycles(), 0);

  // Held, not pressed again: no press bit in the next cycle.
  EXPECT_TRUE(host.publishSensors(v, 260000, 26));
  ASSERT_TRUE(conn.waitTick());
  conn.readSensors();
  EXPECT_EQ(conn.buttons(), 0);
}

TEST(BodyHost, WaitAnswerTimesOut) {
  BodyHost host(19, 2, BodyHost::Mode::InProcess);
  const auto t0 = Clock::now();
  EXPECT_FALSE(host.waitAnswer(0.05));
  const double waited = std::chrono::duration<double>(Clock::now() - t0).count();
  EXPECT_GE(waited, 0.045);
  EXPECT_LT(waited, 2.0);
}

// rUNSWift's Effector picks its slot with
//   for (i = 0; i != actuators_latest && i != actuators_read; ++i);
// which, with actuators_latest parked, stops on the read slot: the index
// then comes back with the value it had before parking. The answer must
// still be seen, every tick, by a program that posts nothing.
// The camera hand-over is answered by Perception's sequence number, not by
// the semaphore alone: a stray perception_done post does not count, the
// program's perceptionDone() for the frame it took does.
TEST(BodyHost, PerceptionDoneCountsOnlyTheAnswerToTheFramePosted) {
  BodyHost host(19, 4, BodyHost::Mode::InProcess);
  al::AgentConnection conn = host.connect();
  al::CameraFrame f{};
  f.frame_index = 7;
  host.publishFrame(f);
  sem_post(&host.camera()->perception_done);  // stray: no sequence number
  EXPECT_FALSE(host.waitPerceptionDone(0.05));

  ASSERT_TRUE(conn.waitFrame());
  EXPECT_EQ(conn.frame().frame_index, 7);
  conn.perceptionDone();
  EXPECT_TRUE(host.waitPerceptionDone(1.0));
  EXPECT_EQ(host.camera()->frames_done.load(), 1);

  // The next frame needs its own answer.
  host.publishFrame(f);
  EXPECT_FALSE(host.waitPerceptionDone(0.05));
  ASSERT_TRUE(conn.waitFrame());
  conn.perceptionDone();
  EXPECT_TRUE(host.waitPerceptionDone(1.0));
  EXPECT_EQ(host.camera()->frames_done.load(), 2);
}

TEST(BodyHost, LockStepSeesAnswersFromTheEffectorSlotLoopQuirk) {
  BodyHost host(19, 4, BodyHost::Mode::InProcess);
  al::AgentData& b = *host.block();
  sem_t* tick = host.tickSemaphore();
  al::SensorValues v{};
  for (int k = 1; k <= 5; ++k) {
    ASSERT_TRUE(host.publishSensors(v, k * 10000, k));
    std::thread client([&] {
      sem_wait(tick);
      al::storeIndex(b.sensors_read, al::loadIndex(b.sensors_latest));
      int i = 0;
      for (; i != b.actuators_latest && i != b.actuators_read; ++i) {
      }
      b.joints[i].angles[al::Joints::HeadYaw] = 0.1f * k;
      b.standing = false;  // the Effector clears the start's `standing`
      al::storeIndex(b.actuators_latest, static_cast<uint8_t>(i));
    });
    ASSERT_TRUE(host.waitAnswer(2.0)) << "tick " << k;
    client.join();
    const int read_before = al::loadIndex(b.actuators_read);
    EXPECT_EQ(host.readActuators().joints.angles[al::Joints::HeadYaw], 0.1f * k) << "tick " << k;
    EXPECT_EQ(al::loadIndex(b.actuators_read), read_before) << "the loop landed on the read slot";
    EXPECT_FALSE(host.answered());
  }
  EXPECT_EQ(host.commandsRead(), 5);
}

// A robot program may write any byte of the block at any time (issue 45):
// an index is read once, checked, and that value used. claimLatest() on an
// index no slot has gives no slot and leaves the read index alone.
TEST(BodyHost, ClaimingAnIndexNoSlotHasGivesNoSlot) {
  for (const uint8_t bad : {uint8_t{3}, uint8_t{250}, al::kActuatorsParked}) {
    volatile uint8_t latest = bad;
    volatile uint8_t read = 1;
    EXPECT_EQ(al::claimLatest(latest, read), al::kNoSlot) << int(bad);
    EXPECT_EQ(al::loadIndex(read), 1) << int(bad);
  }
  volatile uint8_t latest = 2;
  volatile uint8_t read = 0;
  EXPECT_EQ(al::claimLatest(latest, read), 2);
  EXPECT_EQ(al::loadIndex(read), 2);
}

// A hostile program flips actuators_latest between a valid slot and 250
// while the body reads: every command read is the valid slot's, never
// memory beyond the block (this crashed simswift: the body checked the
// index, then loaded it again to index the slots).
TEST(BodyHost, AProgramFlippingTheActuatorIndexCannotMakeTheBodyReadOutsideTheBlock) {
  BodyHost host(19, 5, BodyHost::Mode::InProcess);
  al::AgentData& b = *host.block();
  for (int s = 0; s < al::kSlots; ++s) {
    for (int j = 0; j < al::kNumJoints; ++j) b.joints[s].angles[j] = 0.25f;
    b.stiffen[s] = al::NONE;
  }
  b.standing = false;  // as the Effector's first command leaves it: the body obeys
  std::atomic<bool> stop{false};
  std::thread hostile([&] {
    while (!stop.load(std::memory_order_relaxed)) {
      al::storeIndex(b.actuators_latest, 0);
      al::storeIndex(b.actuators_latest, 250);
    }
  });
  int64_t wrong = 0;
  const auto end = Clock::now() + std::chrono::milliseconds(200);
  int reads = 0;
  while (Clock::now() < end || reads < 1000) {
    const al::ActuatorCommand c = host.readActuators();
    ++reads;
    if (host.commandsRead() > 0) wrong += c.joints.angles[al::Joints::HeadYaw] != 0.25f;
  }
  stop = true;
  hostile.join();
  EXPECT_EQ(wrong, 0) << "of " << reads << " reads";
  EXPECT_GT(host.commandsRead(), 0) << "the valid slot was never read: the test did not race";
  for (int s = 0; s < al::kSlots; ++s) EXPECT_EQ(b.stiffen[s], al::NONE);
}

// A seeded fuzz of libagent's block from a hostile writer: random bytes at
// random places (half of them in the four index bytes), between the body's
// reads and, for 100 ms, from a thread while it reads. The body never reads
// or writes outside the block, whatever the bytes (under ASan this is the
// check that matters; here a stray access crashes or corrupts the heap).
TEST(BodyHost, FuzzingTheBlockFromAHostileWriterNeverCrashesTheBody) {
  for (const bool free_running : {false, true}) {
    BodyHost host(20, 5, BodyHost::Mode::InProcess);
    if (free_running) host.setSync(al::SyncMode::FreeRunning);
    volatile uint8_t* bytes = reinterpret_cast<volatile uint8_t*>(host.block());
    const size_t size = sizeof(al::AgentData);
    std::mt19937_64 rng(45);  // fixed seed: the same cases every run
    al::SensorValues v{};
    for (int k = 1; k <= 3000; ++k) {
      for (int m = static_cast<int>(rng() % 6); m >= 0; --m) {
        const size_t at = rng() % 2 ? rng() % 4 : rng() % size;
        bytes[at] = static_cast<uint8_t>(rng());
      }
      host.publishSensors(v, k * 10000, k);
      host.answered();
      const al::ActuatorCommand c = host.readActuators();
      EXPECT_LE(c.say.size(), static_cast<size_t>(al::kSayTextLength));
      host.standing();
    }
#if !defined(__SANITIZE_THREAD__)
    // A writer racing the reads, as another process does. Not under
    // ThreadSanitizer: it sees this thread's plain stores (another process's
    // writes, which it cannot see) as this process's data race; the
    // ASan+UBSan and Release suites run it.
    std::atomic<bool> stop{false};
    std::thread hostile([&] {
      std::mt19937_64 r(46);
      while (!stop.load(std::memory_order_relaxed)) bytes[r() % 2 ? r() % 4 : r() % size] = static_cast<uint8_t>(r());
    });
    const auto end = Clock::now() + std::chrono::milliseconds(100);
    for (int k = 3001; Clock::now() < end; ++k) {
      host.publishSensors(v, k * 10000, k);
      host.readActuators();
    }
    stop = true;
    hostile.join();
#endif
  }
}

// Free-running: a program that does not wait on the semaphore: the body
// posts once, then counts every cycle as skipped; after more than 50 in a
// row contact is lost and the body sits down as libagent does (200 cycles
// to the middle pose at stiffness 1, 100 to the sit pose at 0.2), then
// stays limp, also once the program answers again, until a STIFFEN.
TEST(BodyHost, ContactLostSitsDownAsLibagentAndStaysLimpUntilStiffened) {
  using LB = bridge::LibagentBehaviour;
  BodyHost host(5, 1, BodyHost::Mode::InProcess);
  host.setSync(al::SyncMode::FreeRunning);
  al::AgentConnection conn = host.connect();
  const al::JointValues stand = an::postureCommand(an::Posture::Stand);
  al::SensorValues v{};
  for (int j = 0; j < al::kNumJoints; ++j) v.joints.angles[j] = stand.angles[j];
  EXPECT_TRUE(host.publishSensors(v, 10000, 1));
  ASSERT_TRUE(conn.waitTick());
  conn.readSensors();
  conn.writeActuators(stand);
  EXPECT_EQ(host.readActuators().joints.angles[al::Joints::LKneePitch], stand.angles[al::Joints::LKneePitch]);
  EXPECT_TRUE(host.publishSensors(v, 20000, 2));  // not taken from here on
  for (int k = 3; k <= 52; ++k) EXPECT_FALSE(host.publishSensors(v, k * 10000, k));
  EXPECT_EQ(host.skippedCycles(), 50);
  EXPECT_EQ(host.extension()->skipped.load(), 50);
  EXPECT_FALSE(host.contactLost());  // libagent: more than MAX_SKIPS (50)
  EXPECT_FALSE(host.publishSensors(v, 530000, 53));
  EXPECT_TRUE(host.contactLost());
  EXPECT_EQ(host.contactLostEvents(), 1);

  const auto& middle = LB::sitMiddleAngles();
  const auto& sit = LB::sitAngles();
  for (int c = 1; c <= LB::kSitMiddleCycles + LB::kSitDownCycles + 1; ++c) {
    const al::JointValues j = host.readActuators().joints;
    SCOPED_TRACE("sit cycle " + std::to_string(c));
    if (c == 1) {  // the first step from the measured angles
      const float k = 1.0f / LB::kSitMiddleCycles;
      EXPECT_NEAR(j.angles[al::Joints::LShoulderPitch], (1 - k) * stand.angles[al::Joints::LShoulderPitch] + k * middle[al::Joints::LShoulderPitch], 1e-6);
    }
    if (c == LB::kSitMiddleCycles) {
      for (int q = 0; q < al::kNumJoints; ++q) EXPECT_NEAR(j.angles[q], middle[q], 1e-5);
      EXPECT_EQ(j.stiffnesses[al::Joints::LKneePitch], LB::kSitMiddleStiffness);
    }
    if (c == LB::kSitMiddleCycles + 1) {
      EXPECT_EQ(j.stiffnesses[al::Joints::LKneePitch], LB::kSitDownStiffness);
    }
    if (c == LB::kSitMiddleCycles + LB::kSitDownCycles) {
      for (int q = 0; q < al::kNumJoints; ++q) EXPECT_NEAR(j.angles[q], sit[q], 1e-5);
      EXPECT_EQ(j.stiffnesses[al::Joints::LKneePitch], LB::kSitDownStiffness);
      EXPECT_FALSE(host.libagent().limp());
    }
    if (c == LB::kSitMiddleCycles + LB::kSitDownCycles + 1) {
      for (int q = 0; q < al::kNumJoints; ++q) EXPECT_EQ(j.stiffnesses[q], 0.0f);
      EXPECT_TRUE(host.libagent().limp());
    }
  }

  // The program takes its tick again: contact is back, the body stays limp.
  ASSERT_TRUE(conn.waitTick());
  EXPECT_TRUE(host.publishSensors(v, 540000, 54));
  EXPECT_FALSE(host.contactLost());
  EXPECT_EQ(host.consecutiveSkipped(), 0);
  conn.readSensors();
  conn.writeActuators(stand);
  EXPECT_EQ(host.readActuators().joints.stiffnesses[al::Joints::LKneePitch], 0.0f);
  // STIFFEN: acted on once (NONE written back), `standing` set, still limp
  // while it is; the program's next command clears it and is obeyed.
  al::ActuatorCommand st;
  st.joints = stand;
  st.stiffen = true;
  conn.writeActuators(st);
  EXPECT_EQ(host.readActuators().joints.stiffnesses[al::Joints::LKneePitch], 0.0f);
  EXPECT_TRUE(host.standing());
  EXPECT_FALSE(host.libagent().limp());
  for (int s = 0; s < al::kSlots; ++s) EXPECT_EQ(host.block()->stiffen[s], al::NONE);
  conn.writeActuators(stand);
  EXPECT_FALSE(host.standing());
  const al::JointValues obeyed = host.readActuators().joints;
  EXPECT_EQ(obeyed.stiffnesses[al::Joints::LKneePitch], stand.stiffnesses[al::Joints::LKneePitch]);
  EXPECT_EQ(obeyed.angles[al::Joints::LKneePitch], stand.angles[al::Joints::LKneePitch]);
}

namespace {
bool exists(const std::string& path, mode_t* mode = nullptr) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return false;
  if (mode) *mode = st.st_mode & 0777;
  return true;
}
std::string shmFile(const std::string& name) { return "/dev/shm" + name; }
std::string semFile(const std::string& name) { return "/dev/shm/sem." + name.substr(1); }
}  // namespace

TEST(BodyHost, NamedObjectsAre0600AndRemovedOnDestructionAndASecondSimulatorNamesTheFirst) {
  // Team 91 player 5 (N = 1006): used by no other test.
  const al::RobotNames n = al::simulationNames(91, 5);
  ASSERT_EQ(n.memory, "/libagent-memory1006");
  {
    simswift::bridge::BodyHostOptions o;
    o.images = true;
    BodyHost host(91, 5, BodyHost::Mode::Named, an::postureCommand(an::Posture::Stand), o);
    EXPECT_EQ(host.memoryName(), n.memory);
    mode_t mode = 0;
    for (const std::string& f : {shmFile(n.memory), shmFile(n.extension), shmFile(n.images)}) {
      ASSERT_TRUE(exists(f, &mode)) << f;
      EXPECT_EQ(mode, 0600u) << f;
    }
    ASSERT_TRUE(exists(semFile(n.semaphore), &mode));
    EXPECT_EQ(mode & 0077u, 0u);  // no access for group/others (umask may only remove bits)
    struct stat st {};
    ASSERT_EQ(stat(shmFile(n.memory).c_str(), &st), 0);
    EXPECT_EQ(st.st_size, 3284);  // exactly AgentData: nothing appended
    ASSERT_NE(host.images(), nullptr);

    // A second simulator for the same robot is refused, naming the live one.
    try {
      BodyHost again(91, 5, BodyHost::Mode::Named);
      FAIL() << "second BodyHost for t91p5 was created";
    } catch (const BridgeError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("belongs to a running simswift (pid " + std::to_string(getpid()) + ")"), std::string::npos)
          << m;
    }
    ASSERT_TRUE(exists(shmFile(n.memory))) << "the failed second host removed the first one's object";

    // Attach by name (as another process would) and round-trip once.
    al::AgentConnection conn = al::AgentConnection::attachByName(91, 5);
    conn.announce(false);
    EXPECT_TRUE(host.clientAnnounced());
    EXPECT_NE(conn.images(), nullptr);
    al::SensorValues v{};
    v.sensors[0] = 1.5f;
    host.publishSensors(v, 10000, 1);
    ASSERT_TRUE(conn.waitTick());
    EXPECT_EQ(conn.readSensors().sensors[0], 1.5f);
    al::JointValues j{};
    j.angles[al::Joints::HeadYaw] = -0.3f;
    conn.writeActuators(j);
    ASSERT_TRUE(host.waitAnswer(1.0));
    EXPECT_EQ(host.readActuators().joints.angles[al::Joints::HeadYaw], -0.3f);
  }
  for (const std::string& f : {shmFile(n.memory), shmFile(n.extension), shmFile(n.images), semFile(n.semaphore)})
    EXPECT_FALSE(exists(f)) << f;
}

// A libagent program that starts first creates the objects (O_CREAT, empty)
// and maps sizeof(AgentData) bytes; the simulator adopts and sizes them, so
// the program's mapping and semaphore become the live ones.
TEST(BodyHost, AdoptsObjectsAProgramCreatedFirst) {
  const al::RobotNames n = al::simulationNames(92, 1);
  const int fd = shm_open(n.memory.c_str(), O_CREAT | O_RDWR, 0600);
  ASSERT_GE(fd, 0);
  void* p = mmap(nullptr, sizeof(al::AgentData), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  close(fd);
  ASSERT_NE(p, MAP_FAILED);
  sem_t* sem = sem_open(n.semaphore.c_str(), O_CREAT, 0600, 0);
  ASSERT_NE(sem, SEM_FAILED);
  sem_post(sem);  // a stray post must not become a tick
  auto* block = static_cast<al::AgentData*>(p);
  {
    BodyHost host(92, 1, BodyHost::Mode::Named);
    // The program's mapping is now backed (reading it before would SIGBUS).
    EXPECT_EQ(al::loadIndex(block->actuators_latest), al::kActuatorsParked);
    int value = -1;
    sem_getvalue(sem, &value);
    EXPECT_EQ(value, 0);
    al::SensorValues v{};
    v.sensors[al::Sensors::InertialSensor_AccZ] = -9.5f;
    ASSERT_TRUE(host.publishSensors(v, 10000, 1));
    ASSERT_EQ(sem_trywait(sem), 0);  // the program's own semaphore got the tick
    const int slot = al::loadIndex(block->sensors_latest);
    EXPECT_EQ(block->sensors[slot].sensors[al::Sensors::InertialSensor_AccZ], -9.5f);
  }
  munmap(p, sizeof(al::AgentData));
  sem_close(sem);
}

TEST(BodyHost, RejectsRobotsOutsideTheTeamsAndPlayers) {
  EXPECT_THROW(BodyHost(256, 1, BodyHost::Mode::InProcess), BridgeError);
  EXPECT_THROW(BodyHost(-1, 1, BodyHost::Mode::InProcess), BridgeError);
  EXPECT_THROW(BodyHost(19, 0, BodyHost::Mode::InProcess), BridgeError);
  EXPECT_THROW(BodyHost(19, 6, BodyHost::Mode::InProcess), BridgeError);
}

// A simulator killed by SIGTERM leaves nothing behind in /dev/shm.
TEST(BodyHost, NamedObjectsAreRemovedOnSigterm) {
  const al::RobotNames n = al::simulationNames(93, 2);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    BodyHost host(93, 2, BodyHost::Mode::Named);
    raise(SIGTERM);
    _exit(0);  // not reached: SIGTERM's default action ends the process
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  for (const std::string& f : {shmFile(n.memory), shmFile(n.extension), semFile(n.semaphore)})
    EXPECT_FALSE(exists(f)) << f;
}

// A simulator killed by SIGKILL cleans nothing: its attached program notices
// within 2 s and stops waiting, and the next simulator for the robot takes
// the stale objects over.
TEST(BodyHost, AfterSigkillTheProgramStopsAndTheNextRunTakesOver) {
  const al::RobotNames n = al::simulationNames(93, 3);
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    BodyHost host(93, 3, BodyHost::Mode::Named);
    const char c = 1;
    if (write(ready[1], &c, 1) != 1) _exit(1);
    for (;;) pause();
  }
  char c = 0;
  ASSERT_EQ(read(ready[0], &c, 1), 1);
  close(ready[0]);
  close(ready[1]);
  {
    al::AgentConnection conn = al::AgentConnection::attachByName(93, 3);
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
    const auto t0 = Clock::now();
    EXPECT_FALSE(conn.waitTick());
    const double waited = std::chrono::duration<double>(Clock::now() - t0).count();
    EXPECT_LT(waited, 2.0);
    EXPECT_FALSE(conn.simulatorAlive());
  }
  // SIGKILL cleans nothing (unless another test's run, in parallel, has
  // already swept the stale objects: the next host works either way).
  {
    BodyHost next(93, 3, BodyHost::Mode::Named);  // stale objects: taken over, no error
    EXPECT_EQ(next.extension()->simulator_pid.load(), getpid());
    al::AgentConnection conn = al::AgentConnection::attachByName(93, 3);
    EXPECT_TRUE(conn.simulatorAlive());
  }
  EXPECT_FALSE(exists(shmFile(n.extension)));
}

namespace {
// A named extension object owned by `pid`, plus a block object, as a
// simulator leaves them.
void fakeRobot(const al::RobotNames& n, int pid) {
  for (const std::string& name : {n.extension, n.memory}) {
    const int fd = shm_open(name.c_str(), O_CREAT | O_RDWR, 0600);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(ftruncate(fd, name == n.extension ? sizeof(al::SimExtension) : sizeof(al::AgentData)), 0);
    if (name == n.extension) {
      void* p = mmap(nullptr, sizeof(al::SimExtension), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
      auto* x = static_cast<al::SimExtension*>(p);
      x->simulator_pid = pid;
      x->magic = al::kExtensionMagic;
      munmap(p, sizeof(al::SimExtension));
    }
    close(fd);
  }
}
}  // namespace

// A run removes what a killed simulator left for other robots, and leaves
// live simulators' robots and the ones it takes over itself alone.
TEST(BodyHost, StaleObjectsOfKilledRunsAreRemoved) {
  const pid_t dead = fork();
  if (dead == 0) _exit(0);
  waitpid(dead, nullptr, 0);
  const al::RobotNames stale = al::simulationNames(95, 1), kept = al::simulationNames(95, 2),
                       live = al::simulationNames(95, 3);
  fakeRobot(stale, dead);
  fakeRobot(kept, dead);
  fakeRobot(live, getpid());
  const std::vector<std::string> removed = simswift::bridge::removeStaleObjects({kept.memory});
  EXPECT_NE(std::find(removed.begin(), removed.end(), stale.memory), removed.end());
  EXPECT_FALSE(exists(shmFile(stale.memory)));
  EXPECT_FALSE(exists(shmFile(stale.extension)));
  EXPECT_TRUE(exists(shmFile(kept.extension)));
  EXPECT_TRUE(exists(shmFile(live.extension)));
  for (const al::RobotNames* n : {&kept, &live}) {
    shm_unlink(n->extension.c_str());
    shm_unlink(n->memory.c_str());
  }
}
