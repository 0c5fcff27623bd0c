// The agent side of libagent: the triple-buffer rule under a concurrent
// writer and reader, the in-process connection, and attach errors.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <memory>
#include <thread>

#include "agent/libagent/AgentConnection.hpp"
#include "agent/libagent/SharedNames.hpp"
#include "agent/libagent/TripleBuffer.hpp"

namespace al = agent::libagent;

namespace {

// A zeroed, initialised block and tick semaphore, as the body side makes them.
struct LocalBody {
  std::unique_ptr<al::SimRobotShm> shm{new al::SimRobotShm()};
  sem_t tick{};
  LocalBody() {
    sem_init(&tick, 0, 0);
    sem_init(&shm->agent.lockstep.motion_done, 1, 0);
    sem_init(&shm->camera.frame_ready, 1, 0);
    sem_init(&shm->camera.perception_done, 1, 0);
    shm->agent.magic = al::kMagic;
    shm->agent.version = al::kVersion;
    shm->camera.magic = al::kMagic;
  }
  ~LocalBody() {
    sem_destroy(&tick);
    sem_destroy(&shm->agent.lockstep.motion_done);
    sem_destroy(&shm->camera.frame_ready);
    sem_destroy(&shm->camera.perception_done);
  }
  void publish(float marker) {
    al::AgentBlock& b = shm->agent;
    const int slot = al::writerSlot(b.sensors_latest, b.sensors_read);
    for (float& v : b.sensors[slot].sensors) v = marker;
    for (float& v : b.sensors[slot].joints.angles) v = marker;
    b.sensors_latest.store(slot);
  }
};

}  // namespace

TEST(TripleBuffer, FreeSlotIsNeitherLatestNorRead) {
  for (int l = 0; l < 3; ++l)
    for (int r = 0; r < 3; ++r) {
      const int f = al::freeSlot(l, r);
      EXPECT_NE(f, l);
      EXPECT_NE(f, r);
    }
}

// A writer publishes slots whose every value is a counter; a reader claims the
// latest slot and checks that it is whole (all values equal: no torn slot)
// and never older than the previous read. Run for 0.3 s of wall clock.
TEST(TripleBuffer, ReaderNeverSeesATornOrOlderSlot) {
  LocalBody body;
  al::AgentBlock& b = body.shm->agent;
  std::atomic<bool> stop{false};
  std::atomic<int64_t> writes{0};
  std::thread writer([&] {
    float k = 1;
    while (!stop.load()) {
      body.publish(k);
      k += 1;
      writes.fetch_add(1);
    }
  });
  int64_t reads = 0, torn = 0, backwards = 0;
  float last = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
  while (std::chrono::steady_clock::now() < end) {
    const int slot = al::claimLatest(b.sensors_latest, b.sensors_read);
    const al::SensorValues copy = b.sensors[slot];
    // The slot is ours until the next claim: it must not change under us.
    const al::SensorValues again = b.sensors[slot];
    const float first = copy.sensors[0];
    for (float v : copy.sensors) torn += v != first;
    for (float v : copy.joints.angles) torn += v != first;
    torn += std::memcmp(&copy, &again, sizeof copy) != 0;
    backwards += first < last;
    last = first;
    ++reads;
  }
  stop = true;
  writer.join();
  EXPECT_GT(reads, 1000);
  EXPECT_GT(writes.load(), 1000);
  EXPECT_EQ(torn, 0);
  EXPECT_EQ(backwards, 0);
}

TEST(AgentConnection, ReadsLatestSensorsAndPublishesActuators) {
  LocalBody body;
  al::AgentConnection conn(&body.shm->agent, &body.tick, &body.shm->camera);
  body.publish(3.5f);
  body.shm->agent.lockstep.sim_time_us = 120000;
  sem_post(&body.tick);
  ASSERT_TRUE(conn.waitTick());
  const al::SensorValues s = conn.readSensors();
  EXPECT_EQ(s.sensors[0], 3.5f);
  EXPECT_EQ(conn.simTimeUs(), 120000);

  al::AgentBlock& b = body.shm->agent;
  const int latest_before = b.actuators_latest.load();
  al::ActuatorCommand cmd;
  cmd.joints.angles[al::Joints::HeadYaw] = 0.25f;
  cmd.joints.stiffnesses[al::Joints::HeadYaw] = 1.0f;
  cmd.say = "hello";
  conn.writeActuators(cmd);
  const int slot = b.actuators_latest.load();
  EXPECT_NE(slot, latest_before);             // a fresh slot...
  EXPECT_NE(slot, b.actuators_read.load());   // ...not the one being read
  EXPECT_EQ(b.joints[slot].angles[al::Joints::HeadYaw], 0.25f);
  EXPECT_STREQ(b.say_text[slot], "hello");
  // The lock-step acknowledgement was posted exactly once.
  EXPECT_EQ(sem_trywait(&b.lockstep.motion_done), 0);
  EXPECT_NE(sem_trywait(&b.lockstep.motion_done), 0);
}

TEST(AgentConnection, WaitTickReturnsFalseOnShutdown) {
  LocalBody body;
  al::AgentConnection conn(&body.shm->agent, &body.tick);
  std::thread t([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    body.shm->agent.lockstep.shutdown = 1;
    sem_post(&body.tick);
  });
  EXPECT_FALSE(conn.waitTick());
  t.join();
}

TEST(AgentConnection, AttachToMissingRobotSaysWhatToCheck) {
  try {
    // No simulator creates team 1 player 5 in this test program.
    al::AgentConnection::attachNamed("/libagent-memory-test-missing-" + std::to_string(getpid()),
                                     "/libagent-semaphore-test-missing");
    FAIL() << "attach to a missing block succeeded";
  } catch (const al::AgentError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("no simulated robot named /libagent-memory-test-missing"), std::string::npos) << m;
    EXPECT_NE(m.find("external"), std::string::npos) << m;
  }
  EXPECT_EQ(al::memoryName(1, 2), "/libagent-memory-8");
  EXPECT_EQ(al::semaphoreName(0, 5), "/libagent-semaphore-5");
}

namespace {
// Creates a named shm of `size` bytes with the given header; unlinks on exit.
struct FakeShm {
  std::string name;
  FakeShm(size_t size, uint32_t magic, uint32_t version)
      : name("/libagent-memory-test-fake-" + std::to_string(getpid())) {
    const int fd = shm_open(name.c_str(), O_CREAT | O_RDWR | O_TRUNC, 0600);
    EXPECT_GE(fd, 0);
    EXPECT_EQ(ftruncate(fd, static_cast<off_t>(size)), 0);
    if (size >= 8) {
      uint32_t header[2] = {magic, version};
      EXPECT_EQ(pwrite(fd, header, sizeof header, 0), static_cast<ssize_t>(sizeof header));
    }
    close(fd);
  }
  ~FakeShm() { shm_unlink(name.c_str()); }
};

std::string attachError(const std::string& name) {
  try {
    al::AgentConnection::attachNamed(name, "/libagent-semaphore-test-none");
  } catch (const al::AgentError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(AgentConnection, AttachChecksSizeMagicAndVersion) {
  {
    FakeShm f(16, al::kMagic, al::kVersion);
    const std::string m = attachError(f.name);
    EXPECT_NE(m.find("smaller than an AgentBlock"), std::string::npos) << m;
  }
  {
    FakeShm f(sizeof(al::SimRobotShm), 0xdeadbeef, al::kVersion);
    const std::string m = attachError(f.name);
    EXPECT_NE(m.find("magic"), std::string::npos) << m;
  }
  {
    FakeShm f(sizeof(al::SimRobotShm), al::kMagic, al::kVersion + 7);
    const std::string m = attachError(f.name);
    EXPECT_NE(m.find("version"), std::string::npos) << m;
  }
  {
    // A good block but no semaphore: the message names the semaphore.
    FakeShm f(sizeof(al::SimRobotShm), al::kMagic, al::kVersion);
    const std::string m = attachError(f.name);
    EXPECT_NE(m.find("/libagent-semaphore-test-none"), std::string::npos) << m;
  }
}
