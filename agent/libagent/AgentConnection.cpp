#include "agent/libagent/AgentConnection.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <ctime>
#include <chrono>
#include <thread>
#include <cstring>

#include "agent/libagent/SharedNames.hpp"
#include "agent/libagent/TripleBuffer.hpp"

namespace agent::libagent {

AgentConnection::AgentConnection(AgentBlock* block, sem_t* tick, CameraBlock* camera)
    : block_(block), tick_(tick), camera_(camera) {
  if (!block || !tick) throw AgentError("AgentConnection: null block or tick semaphore");
  if (block->magic != kMagic || block->version != kVersion)
    throw AgentError("AgentConnection: in-process block has bad magic/version");
}

AgentConnection AgentConnection::attachByName(int team, int player) {
  AgentConnection c = attachNamed(memoryName(team, player), semaphoreName(team, player));
  // The images block exists only while the simulator renders; without it
  // the program runs on the frame's observations alone.
  const std::string images = cameraImagesName(team, player);
  const int fd = shm_open(images.c_str(), O_RDONLY, 0);
  if (fd >= 0) {
    struct stat st {};
    if (fstat(fd, &st) == 0 && static_cast<size_t>(st.st_size) >= sizeof(CameraImages)) {
      void* p = mmap(nullptr, sizeof(CameraImages), PROT_READ, MAP_SHARED, fd, 0);
      if (p != MAP_FAILED) {
        c.images_mapping_ = p;
        c.images_ = static_cast<const CameraImages*>(p);
      }
    }
    close(fd);
  }
  return c;
}

AgentConnection AgentConnection::attachNamed(const std::string& memory, const std::string& semaphore) {
  AgentConnection c;
  c.memory_name_ = memory;
  const int fd = shm_open(memory.c_str(), O_RDWR, 0);
  if (fd < 0) {
    if (errno == ENOENT)
      throw AgentError("no simulated robot named " + memory +
                       ": is simswift running with external robots (program: external)?");
    throw AgentError("cannot open " + memory + ": " + std::strerror(errno));
  }
  struct stat st {};
  if (fstat(fd, &st) != 0 || static_cast<size_t>(st.st_size) < sizeof(AgentBlock)) {
    close(fd);
    throw AgentError(memory + " is " + std::to_string(st.st_size) + " bytes, smaller than an AgentBlock (" +
                     std::to_string(sizeof(AgentBlock)) + "): not a libagent block, or another build");
  }
  c.mapping_size_ = static_cast<size_t>(st.st_size);
  void* p = mmap(nullptr, c.mapping_size_, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  close(fd);
  if (p == MAP_FAILED) throw AgentError("cannot map " + memory + ": " + std::strerror(errno));
  c.mapping_ = p;
  c.block_ = static_cast<AgentBlock*>(p);
  // The simulator writes the magic last; a block caught while being set up
  // reads 0 for a moment (wall-clock wait: attach only, never simulation).
  const volatile uint32_t* magic = &c.block_->magic;
  for (int i = 0; i < 100 && *magic == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  if (c.block_->magic != kMagic)
    throw AgentError(memory + " has magic " + std::to_string(c.block_->magic) + ", expected " +
                     std::to_string(kMagic) + ": not a simswift libagent block");
  if (c.block_->version != kVersion)
    throw AgentError(memory + " has version " + std::to_string(c.block_->version) +
                     ", this program speaks " + std::to_string(kVersion) +
                     ": rebuild the robot program against the same simswift");
  if (c.mapping_size_ >= sizeof(SimRobotShm)) {
    auto* shm = static_cast<SimRobotShm*>(p);
    if (shm->camera.magic == kMagic) c.camera_ = &shm->camera;
  }
  sem_t* s = sem_open(semaphore.c_str(), 0);
  if (s == SEM_FAILED)
    throw AgentError("cannot open semaphore " + semaphore + " for " + memory + ": " + std::strerror(errno));
  c.tick_ = s;
  c.named_sem_ = true;
  return c;
}

AgentConnection::AgentConnection(AgentConnection&& o) noexcept
    : block_(o.block_), tick_(o.tick_), camera_(o.camera_), images_(o.images_),
      images_mapping_(o.images_mapping_), mapping_(o.mapping_),
      mapping_size_(o.mapping_size_), named_sem_(o.named_sem_), memory_name_(std::move(o.memory_name_)) {
  o.block_ = nullptr;
  o.tick_ = nullptr;
  o.camera_ = nullptr;
  o.images_ = nullptr;
  o.images_mapping_ = nullptr;
  o.mapping_ = nullptr;
  o.named_sem_ = false;
}

AgentConnection::~AgentConnection() { release(); }

void AgentConnection::release() {
  if (named_sem_ && tick_) sem_close(tick_);
  if (mapping_) munmap(mapping_, mapping_size_);
  if (images_mapping_) munmap(images_mapping_, sizeof(CameraImages));
  mapping_ = nullptr;
  images_mapping_ = nullptr;
  images_ = nullptr;
  tick_ = nullptr;
  block_ = nullptr;
}

void AgentConnection::announce(bool perception) {
  if (camera_) camera_->consumer.store(perception ? 1 : 0);
  // Last: the simulator reads `consumer` once it sees `attached`.
  block_->lockstep.attached.store(mapping_ ? static_cast<int32_t>(getpid()) : 1);
}

namespace {
// Waits on `s`. Attached by name, wakes every second (wall clock, liveness
// only) to check the simulator still exists: one that died or ended without
// posting would otherwise leave this program blocked forever.
bool waitOrSimulatorGone(sem_t* s, const std::string& name, bool named, const char* what) {
  for (;;) {
    if (!named) {
      if (sem_wait(s) == 0) return true;
    } else {
      timespec deadline{};
      clock_gettime(CLOCK_MONOTONIC, &deadline);
      deadline.tv_sec += 1;
      if (sem_clockwait(s, CLOCK_MONOTONIC, &deadline) == 0) return true;
      if (errno == ETIMEDOUT) {
        const int fd = shm_open(name.c_str(), O_RDONLY, 0);
        if (fd < 0 && errno == ENOENT) {
          std::fprintf(stderr, "libagent: %s is gone: the simulator has ended\n", name.c_str());
          return false;
        }
        if (fd >= 0) close(fd);
        continue;
      }
    }
    if (errno != EINTR && errno != ETIMEDOUT)
      throw AgentError(std::string("waiting on ") + what + ": " + std::strerror(errno));
  }
}
}  // namespace

bool AgentConnection::waitTick() {
  if (shutdown()) return false;
  if (!waitOrSimulatorGone(tick_, memory_name_, mapping_ != nullptr, "tick")) return false;
  return !shutdown();
}

SensorValues AgentConnection::readSensors() {
  const int slot = claimLatest(block_->sensors_latest, block_->sensors_read);
  return block_->sensors[slot];
}

void AgentConnection::writeActuators(const ActuatorCommand& cmd) {
  const int slot = writerSlot(block_->actuators_latest, block_->actuators_read);
  block_->joints[slot] = cmd.joints;
  block_->leds[slot] = cmd.leds;
  block_->sonar[slot] = cmd.sonar;
  block_->stiffen[slot] = cmd.stiffen;
  const size_t n = std::min(cmd.say.size(), static_cast<size_t>(kSayTextLength - 1));
  std::memcpy(block_->say_text[slot], cmd.say.data(), n);
  block_->say_text[slot][n] = '\0';
  block_->actuators_latest.store(slot);
  sem_post(&block_->lockstep.motion_done);
}

void AgentConnection::writeActuators(const JointValues& joints, const LedCommand* leds, SonarMode sonar,
                                     bool stiffen, const std::string& say) {
  ActuatorCommand cmd;
  cmd.joints = joints;
  if (leds) cmd.leds = *leds;
  cmd.sonar = sonar;
  cmd.stiffen = stiffen;
  cmd.say = say;
  writeActuators(cmd);
}

bool AgentConnection::waitFrame() {
  if (!camera_) throw AgentError("waitFrame: this robot has no camera block");
  if (camera_->shutdown.load()) return false;
  if (!waitOrSimulatorGone(&camera_->frame_ready, memory_name_, mapping_ != nullptr, "frame_ready")) return false;
  return camera_->shutdown.load() == 0;
}

void AgentConnection::perceptionDone() { sem_post(&camera_->perception_done); }

}  // namespace agent::libagent
