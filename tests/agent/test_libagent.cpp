// The agent side of libagent: the triple-buffer rule under a concurrent
// writer and reader, the in-process connection, names, attach errors, and
// noticing a simulator that was killed.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <memory>
#include <thread>

#include "common/libagent/AgentConnection.hpp"
#include "common/libagent/SharedNames.hpp"
#include "common/libagent/TripleBuffer.hpp"

namespace al = common::libagent;

namespace {

// A zeroed block, extension and tick semaphore, as the body side makes them.
struct LocalBody {
  std::unique_ptr<al::AgentData> block{new al::AgentData()};
  std::unique_ptr<al::SimExtension> ext{new al::SimExtension()};
  sem_t tick{};
  LocalBody() {
    sem_init(&tick, 0, 0);
    sem_init(&ext->answered, 1, 0);
    sem_init(&ext->camera.frame_ready, 1, 0);
    sem_init(&ext->camera.perception_done, 1, 0);
    ext->magic = al::kExtensionMagic;
    ext->version = al::kExtensionVersion;
    al::storeIndex(block->actuators_latest, al::kActuatorsParked);
  }
  ~LocalBody() {
    sem_destroy(&tick);
    sem_destroy(&ext->answered);
    sem_destroy(&ext->camera.frame_ready);
    sem_destroy(&ext->camera.perception_done);
  }
  void publish(float marker, int64_t t_us = 0) {
    al::AgentData& b = *block;
    const int slot = al::writerSlot(b.sensors_latest, b.sensors_read);
    for (float& v : b.sensors[slot].sensors) v = marker;
    for (float& v : b.sensors[slot].joints.angles) v = marker;
    ext->slot_time_us[slot] = t_us;
    al::storeIndex(b.sensors_latest, static_cast<uint8_t>(slot));
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
  // Parked latest (out of range): any slot but the read one.
  for (int r = 0; r < 3; ++r) EXPECT_NE(al::freeSlot(al::kActuatorsParked, r), r);
}

// A writer publishes slots whose every value is a counter; a reader claims the
// latest slot and checks that it is whole (all values equal: no torn slot)
// and never older than the previous read. Run for 0.3 s of wall clock.
TEST(TripleBuffer, ReaderNeverSeesATornOrOlderSlot) {
  LocalBody body;
  al::AgentData& b = *body.block;
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

TEST(AgentConnection, ReadsLatestSensorsAndPublishesActuatorsAsLibagentClientsDo) {
  LocalBody body;
  al::AgentConnection conn(body.block.get(), &body.tick, body.ext.get());
  body.publish(3.5f, 120000);
  sem_post(&body.tick);
  ASSERT_TRUE(conn.waitTick());
  const al::SensorValues s = conn.readSensors();
  EXPECT_EQ(s.sensors[0], 3.5f);
  EXPECT_EQ(conn.simTimeUs(), 120000);
  al::AgentData& b = *body.block;
  EXPECT_EQ(al::loadIndex(b.sensors_read), al::loadIndex(b.sensors_latest));  // Touch's claim

  // The body parked actuators_latest; the command lands in a slot other than
  // the read one and unparks it.
  al::ActuatorCommand cmd;
  cmd.joints.angles[al::Joints::HeadYaw] = 0.25f;
  cmd.joints.stiffnesses[al::Joints::HeadYaw] = 1.0f;
  cmd.say = "hello, this text is longer than thirty-five characters";
  cmd.stiffen = true;
  cmd.leds.left_ear = 0x3ff;
  cmd.leds.chest.green = true;
  conn.writeActuators(cmd);
  const int slot = al::loadIndex(b.actuators_latest);
  ASSERT_TRUE(al::validSlot(slot));
  EXPECT_NE(slot, al::loadIndex(b.actuators_read));
  EXPECT_EQ(b.joints[slot].angles[al::Joints::HeadYaw], 0.25f);
  EXPECT_EQ(std::strlen(b.sayTexts[slot]), 34u);  // truncated to the 35-byte slot
  EXPECT_EQ(std::strncmp(b.sayTexts[slot], "hello, this text", 16), 0);
  EXPECT_EQ(b.stiffen[slot], al::STIFFEN);
  EXPECT_EQ(b.leds[slot].left_ear, 0x3ff);
  EXPECT_TRUE(b.leds[slot].chest.green);
  // The wake-up hint was posted exactly once.
  EXPECT_EQ(sem_trywait(&body.ext->answered), 0);
  EXPECT_NE(sem_trywait(&body.ext->answered), 0);
}

TEST(AgentConnection, WaitTickReturnsFalseOnShutdown) {
  LocalBody body;
  al::AgentConnection conn(body.block.get(), &body.tick, body.ext.get());
  std::thread t([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    body.ext->shutdown = 1;
    sem_post(&body.tick);
  });
  EXPECT_FALSE(conn.waitTick());
  t.join();
}

TEST(LibagentNames, SimulationRuleAndBareNames) {
  // N = SPL team number x 11 + player, no separator (rUNSWift 2017 release, robot/libagent).
  const al::RobotNames n = al::simulationNames(19, 1);
  EXPECT_EQ(n.memory, "/libagent-memory210");
  EXPECT_EQ(n.semaphore, "/libagent-semaphore210");
  EXPECT_EQ(n.extension, "/libagent-simswift210");
  EXPECT_EQ(n.images, "/libagent-simswift-images210");
  EXPECT_EQ(al::simulationNames(5, 3).memory, "/libagent-memory58");
  EXPECT_EQ(al::bareNames().memory, "/libagent-memory");
  EXPECT_EQ(al::bareNames().semaphore, "/libagent-semaphore");
  EXPECT_EQ(al::robotTag(19, 1), "t19p1");
}

namespace {
al::RobotNames testNames(const char* what) {
  return al::namesWithSuffix("-test-" + std::string(what) + "-" + std::to_string(getpid()));
}

// A named extension object of `size` bytes holding `ext`; unlinked on exit.
struct FakeExtension {
  std::string name;
  al::SimExtension* ext = nullptr;
  size_t size;
  FakeExtension(const std::string& n, size_t sz) : name(n), size(sz) {
    const int fd = shm_open(name.c_str(), O_CREAT | O_RDWR | O_TRUNC, 0600);
    EXPECT_GE(fd, 0);
    EXPECT_EQ(ftruncate(fd, static_cast<off_t>(size)), 0);
    if (size >= sizeof(al::SimExtension))
      ext = static_cast<al::SimExtension*>(mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0));
    close(fd);
  }
  ~FakeExtension() {
    if (ext) munmap(ext, size);
    shm_unlink(name.c_str());
  }
};

std::string attachError(const al::RobotNames& names) {
  try {
    al::AgentConnection::attach(names);
  } catch (const al::AgentError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(AgentConnection, AttachToMissingRobotSaysWhatToCheck) {
  const std::string m = attachError(testNames("missing"));
  EXPECT_NE(m.find("no simulated robot named /libagent-memory-test-missing"), std::string::npos) << m;
  EXPECT_NE(m.find("program: external"), std::string::npos) << m;
}

TEST(AgentConnection, AttachChecksSizeMagicVersionAndOwner) {
  const al::RobotNames names = testNames("fake");
  {
    FakeExtension f(names.extension, 16);
    const std::string m = attachError(names);
    EXPECT_NE(m.find("smaller than expected"), std::string::npos) << m;
  }
  {
    FakeExtension f(names.extension, sizeof(al::SimExtension));
    f.ext->magic = 0xdeadbeef;
    const std::string m = attachError(names);
    EXPECT_NE(m.find("magic"), std::string::npos) << m;
  }
  {
    FakeExtension f(names.extension, sizeof(al::SimExtension));
    f.ext->magic = al::kExtensionMagic;
    f.ext->version = al::kExtensionVersion + 7;
    const std::string m = attachError(names);
    EXPECT_NE(m.find("version"), std::string::npos) << m;
  }
  {
    // Owned by a process that has exited: stale, not attachable.
    const pid_t child = fork();
    if (child == 0) _exit(0);
    waitpid(child, nullptr, 0);
    FakeExtension f(names.extension, sizeof(al::SimExtension));
    f.ext->magic = al::kExtensionMagic;
    f.ext->version = al::kExtensionVersion;
    f.ext->simulator_pid = child;
    const std::string m = attachError(names);
    EXPECT_NE(m.find("is gone"), std::string::npos) << m;
  }
  {
    // Owned by this (live) process, but no libagent block: names the block.
    FakeExtension f(names.extension, sizeof(al::SimExtension));
    f.ext->magic = al::kExtensionMagic;
    f.ext->version = al::kExtensionVersion;
    f.ext->simulator_pid = getpid();
    const std::string m = attachError(names);
    EXPECT_NE(m.find(names.memory), std::string::npos) << m;
  }
}

TEST(Liveness, ProcessAliveSeesExitsZombiesAndRecycledPids) {
  EXPECT_TRUE(al::processAlive(getpid(), 0));
  EXPECT_TRUE(al::processAlive(getpid(), al::processStartTime(getpid())));
  EXPECT_FALSE(al::processAlive(getpid(), al::processStartTime(getpid()) + 1));  // another process, same pid
  EXPECT_FALSE(al::processAlive(0, 0));
  const pid_t child = fork();
  if (child == 0) _exit(0);
  // Not yet reaped: a zombie is gone too.
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(al::processAlive(child, 0));
  waitpid(child, nullptr, 0);
  EXPECT_FALSE(al::processAlive(child, 0));
}
