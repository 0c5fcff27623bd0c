#include "common/libagent/AgentConnection.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <thread>

#include "common/libagent/TripleBuffer.hpp"

namespace common::libagent {

namespace {

// How often a named connection, blocked on a semaphore, looks whether the
// simulator still exists (wall clock, liveness only): well inside the 2 s in
// which a program must notice a killed simulator.
constexpr long kLivenessCheckNs = 250000000L;

// Maps `name` read-write, at least `size` bytes; null with `error` set if it
// does not exist or is smaller.
void* mapNamed(const std::string& name, size_t size, bool write, std::string* error, bool* missing) {
  *missing = false;
  const int fd = shm_open(name.c_str(), write ? O_RDWR : O_RDONLY, 0);
  if (fd < 0) {
    *missing = errno == ENOENT;
    *error = "cannot open " + name + ": " + std::strerror(errno);
    return nullptr;
  }
  struct stat st {};
  if (fstat(fd, &st) != 0 || static_cast<size_t>(st.st_size) < size) {
    close(fd);
    *error = name + " is " + std::to_string(st.st_size) + " bytes, smaller than expected (" + std::to_string(size) +
             "): not set up yet, or another build";
    return nullptr;
  }
  void* p = mmap(nullptr, size, write ? PROT_READ | PROT_WRITE : PROT_READ, MAP_SHARED, fd, 0);
  close(fd);
  if (p == MAP_FAILED) {
    *error = "cannot map " + name + ": " + std::strerror(errno);
    return nullptr;
  }
  return p;
}

}  // namespace

AgentConnection AgentConnection::extensionOnly(SimExtension* ext) {
  if (!ext) throw AgentError("AgentConnection: null extension");
  AgentConnection c;
  c.ext_ = ext;
  return c;
}

AgentConnection::AgentConnection(AgentData* block, sem_t* tick, SimExtension* ext)
    : block_(block), tick_(tick), ext_(ext) {
  if (!block || !tick || !ext) throw AgentError("AgentConnection: null block, tick semaphore or extension");
}

AgentConnection AgentConnection::attachByName(int team, int player) { return attach(simulationNames(team, player)); }

AgentConnection AgentConnection::attach(const RobotNames& names) {
  AgentConnection c;
  c.named_ = true;
  c.names_ = names;
  std::string error;
  bool missing = false;
  // The extension first: it says whether a live simulator owns the robot.
  c.ext_map_ = mapNamed(names.extension, sizeof(SimExtension), true, &error, &missing);
  if (!c.ext_map_) {
    if (missing)
      throw AgentError("no simulated robot named " + names.memory + " (" + names.extension +
                       " does not exist): is simswift running this robot with program: external?");
    throw AgentError(error);
  }
  c.ext_ = static_cast<SimExtension*>(c.ext_map_);
  // The simulator writes the magic last; a robot caught while being set up
  // reads 0 for a moment (wall-clock wait: attach only, never simulation).
  const volatile uint32_t* magic = &c.ext_->magic;
  for (int i = 0; i < 100 && *magic != kExtensionMagic; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  if (c.ext_->magic != kExtensionMagic)
    throw AgentError(names.extension + " has magic " + std::to_string(c.ext_->magic) +
                     ": not a simswift extension object (yet)");
  if (c.ext_->version != kExtensionVersion)
    throw AgentError(names.extension + " has version " + std::to_string(c.ext_->version) + ", this program speaks " +
                     std::to_string(kExtensionVersion) + ": rebuild the robot program against the same simswift");
  c.sim_pid_ = c.ext_->simulator_pid.load();
  c.sim_start_ = c.ext_->simulator_start.load();
  if (!processAlive(c.sim_pid_, c.sim_start_))
    throw AgentError(names.memory + ": its simulator (pid " + std::to_string(c.sim_pid_) +
                     ") is gone; the next simswift run for this robot replaces the stale objects");
  if (c.ext_->shutdown.load()) throw AgentError(names.memory + ": the simulator has ended this run");

  c.block_map_ = mapNamed(names.memory, sizeof(AgentData), true, &error, &missing);
  if (!c.block_map_) throw AgentError(error);
  c.block_ = static_cast<AgentData*>(c.block_map_);
  sem_t* s = sem_open(names.semaphore.c_str(), 0);
  if (s == SEM_FAILED)
    throw AgentError("cannot open semaphore " + names.semaphore + " for " + names.memory + ": " +
                     std::strerror(errno));
  c.tick_ = s;
  // The images exist only while the simulator renders; without them the
  // program runs on the frame's observations alone.
  c.images_map_ = mapNamed(names.images, sizeof(CameraImages), false, &error, &missing);
  c.images_ = static_cast<const CameraImages*>(c.images_map_);
  return c;
}

AgentConnection::AgentConnection(AgentConnection&& o) noexcept
    : block_(o.block_), tick_(o.tick_), ext_(o.ext_), images_(o.images_), last_slot_(o.last_slot_),
      named_(o.named_), names_(std::move(o.names_)), block_map_(o.block_map_), ext_map_(o.ext_map_),
      images_map_(o.images_map_), sim_pid_(o.sim_pid_), sim_start_(o.sim_start_), frame_taken_(o.frame_taken_) {
  o.block_ = nullptr;
  o.tick_ = nullptr;
  o.ext_ = nullptr;
  o.images_ = nullptr;
  o.named_ = false;
  o.block_map_ = o.ext_map_ = o.images_map_ = nullptr;
}

AgentConnection::~AgentConnection() { release(); }

void AgentConnection::release() {
  if (named_ && tick_) sem_close(tick_);
  if (block_map_) munmap(block_map_, sizeof(AgentData));
  if (ext_map_) munmap(ext_map_, sizeof(SimExtension));
  if (images_map_) munmap(images_map_, sizeof(CameraImages));
  block_map_ = ext_map_ = images_map_ = nullptr;
  images_ = nullptr;
  tick_ = nullptr;
  block_ = nullptr;
  ext_ = nullptr;
}

void AgentConnection::announce(bool perception) {
  ext_->camera.consumer.store(perception ? 1 : 0);
  // Last: the simulator reads `consumer` once it sees the program.
  ext_->client_pid.store(named_ ? static_cast<int32_t>(getpid()) : 1);
}

bool AgentConnection::simulatorAlive() const { return !named_ || processAlive(sim_pid_, sim_start_); }

// Waits on `s`. Attached by name, wakes every kLivenessCheckNs (wall clock,
// liveness only) to check the simulator still exists: one that was killed
// would otherwise leave this program blocked forever.
bool AgentConnection::waitOn(sem_t* s, const char* what) {
  for (;;) {
    if (!named_) {
      if (sem_wait(s) == 0) return true;
    } else {
      timespec deadline{};
      clock_gettime(CLOCK_MONOTONIC, &deadline);
      deadline.tv_nsec += kLivenessCheckNs;
      if (deadline.tv_nsec >= 1000000000L) {
        deadline.tv_sec += 1;
        deadline.tv_nsec -= 1000000000L;
      }
      if (sem_clockwait(s, CLOCK_MONOTONIC, &deadline) == 0) return true;
      if (errno == ETIMEDOUT) {
        if (ext_->shutdown.load()) return false;
        if (!simulatorAlive()) {
          std::fprintf(stderr, "libagent: the simulator of %s (pid %d) is gone: stopping\n", names_.memory.c_str(),
                       sim_pid_);
          return false;
        }
        continue;
      }
    }
    if (errno != EINTR && errno != ETIMEDOUT)
      throw AgentError(std::string("waiting on ") + what + ": " + std::strerror(errno));
  }
}

bool AgentConnection::waitTick() {
  if (shutdown()) return false;
  if (!waitOn(tick_, "the tick semaphore")) return false;
  return !shutdown();
}

bool AgentConnection::takeTick() {
  if (shutdown()) return false;
  return sem_trywait(tick_) == 0;
}

SensorValues AgentConnection::readSensors() {
  // No valid slot (never from simswift): the last one claimed again.
  const int slot = claimLatest(block_->sensors_latest, block_->sensors_read);
  if (validSlot(slot)) last_slot_ = slot;
  return block_->sensors[last_slot_];
}

void AgentConnection::writeActuators(const ActuatorCommand& cmd) {
  // A slot that is neither latest nor being read. When the simulator has
  // parked actuators_latest (lock-step), that is any slot but the read one.
  const int slot = writerSlot(block_->actuators_latest, block_->actuators_read);
  block_->joints[slot] = cmd.joints;
  block_->leds[slot] = cmd.leds;
  block_->sonar[slot] = cmd.sonar;
  block_->stiffen[slot] = cmd.stiffen ? STIFFEN : NONE;
  const size_t n = std::min(cmd.say.size(), static_cast<size_t>(kSayTextLength - 1));
  std::memcpy(block_->sayTexts[slot], cmd.say.data(), n);
  block_->sayTexts[slot][n] = '\0';
  // libagent's Effector clears `standing` once the body side has set it.
  if (block_->standing) block_->standing = false;
  storeIndex(block_->actuators_latest, static_cast<uint8_t>(slot));
  sem_post(&ext_->answered);
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
  if (ext_->camera.shutdown.load()) return false;
  if (!waitOn(&ext_->camera.frame_ready, "frame_ready")) return false;
  // Acquire: pairs with the simulator's release before its post, so the
  // frame (and everything the simulator wrote before it) is visible.
  frame_taken_ = ext_->camera.frames_posted.load(std::memory_order_acquire);
  return ext_->camera.shutdown.load() == 0;
}

bool AgentConnection::takeFrame() {
  if (ext_->camera.shutdown.load()) return false;
  if (sem_trywait(&ext_->camera.frame_ready) != 0) return false;
  frame_taken_ = ext_->camera.frames_posted.load(std::memory_order_acquire);  // as waitFrame()
  return true;
}

void AgentConnection::perceptionDone() {
  // Release: everything this frame's Perception wrote (team outbox, ...)
  // is visible to the simulator once it loads the number.
  ext_->camera.frames_done.store(frame_taken_, std::memory_order_release);
  sem_post(&ext_->camera.perception_done);
}

}  // namespace common::libagent
