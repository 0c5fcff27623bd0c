#include "sim/bridge/BodyHost.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>

#include "agent/libagent/TripleBuffer.hpp"

namespace simswift::bridge {

namespace al = agent::libagent;

namespace {
std::string sysError(const std::string& what) { return what + ": " + std::strerror(errno); }

// Absolute CLOCK_MONOTONIC deadline `timeout_s` from now (watchdog only).
timespec deadlineIn(double timeout_s) {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  const double whole = std::floor(timeout_s);
  now.tv_sec += static_cast<time_t>(whole);
  now.tv_nsec += static_cast<long>((timeout_s - whole) * 1e9);
  if (now.tv_nsec >= 1000000000L) {
    now.tv_sec += 1;
    now.tv_nsec -= 1000000000L;
  }
  return now;
}

bool waitWithTimeout(sem_t* s, double timeout_s) {
  const timespec deadline = deadlineIn(timeout_s);
  for (;;) {
    if (sem_clockwait(s, CLOCK_MONOTONIC, &deadline) == 0) return true;
    if (errno == ETIMEDOUT) return false;
    if (errno != EINTR) throw BridgeError(sysError("sem_clockwait"));
  }
}
}  // namespace

BodyHost::BodyHost(int team, int player, Mode mode, const al::JointValues& initial)
    : team_(team), player_(player), tag_(al::robotTag(team, player)), mode_(mode) {
  if (team < 0 || team >= al::kMaxTeams || player < al::kMinPlayer || player > al::kMaxPlayer)
    throw BridgeError("robot " + tag_ + ": team must be 0.." + std::to_string(al::kMaxTeams - 1) +
                      " and player 1.." + std::to_string(al::kMaxPlayer));
  if (mode == Mode::InProcess) {
    owned_.reset(new al::SimRobotShm());  // value-initialised: all zero
    shm_ = owned_.get();
    if (sem_init(&tick_local_, 0, 0) != 0) throw BridgeError(sysError("sem_init"));
    tick_ = &tick_local_;
  } else {
    memory_name_ = al::memoryName(team, player);
    semaphore_name_ = al::semaphoreName(team, player);
    const int fd = shm_open(memory_name_.c_str(), O_CREAT | O_EXCL | O_RDWR, 0600);
    if (fd < 0) {
      if (errno == EEXIST)
        throw BridgeError(memory_name_ + " already exists: another simswift runs robot " + tag_ +
                          ", or a crashed run left it behind (remove /dev/shm" + memory_name_ + ")");
      throw BridgeError(sysError("shm_open " + memory_name_));
    }
    cleanup::registerShm(memory_name_);
    fchmod(fd, 0600);  // independent of the umask
    if (ftruncate(fd, sizeof(al::SimRobotShm)) != 0) {
      const std::string e = sysError("ftruncate " + memory_name_);
      close(fd);
      shm_unlink(memory_name_.c_str());
      cleanup::unregister(memory_name_);
      throw BridgeError(e);
    }
    void* p = mmap(nullptr, sizeof(al::SimRobotShm), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    close(fd);
    if (p == MAP_FAILED) {
      const std::string e = sysError("mmap " + memory_name_);
      shm_unlink(memory_name_.c_str());
      cleanup::unregister(memory_name_);
      throw BridgeError(e);
    }
    shm_ = static_cast<al::SimRobotShm*>(p);  // ftruncate zero-fills
    sem_t* s = sem_open(semaphore_name_.c_str(), O_CREAT | O_EXCL, 0600, 0);
    if (s == SEM_FAILED) {
      const std::string e = errno == EEXIST
                                ? semaphore_name_ + " already exists: another simswift runs robot " + tag_ +
                                      ", or a crashed run left it (remove /dev/shm/sem." +
                                      semaphore_name_.substr(1) + ")"
                                : sysError("sem_open " + semaphore_name_);
      munmap(shm_, sizeof(al::SimRobotShm));
      shm_unlink(memory_name_.c_str());
      cleanup::unregister(memory_name_);
      throw BridgeError(e);
    }
    cleanup::registerSem(semaphore_name_);
    tick_ = s;
  }

  al::AgentBlock& b = shm_->agent;
  b.version = al::kVersion;
  b.sensors_read = 0;
  b.sensors_latest = 0;
  b.actuators_latest = 0;
  b.actuators_read = 0;
  for (int s = 0; s < al::kSlots; ++s) {
    b.joints[s] = initial;
    b.sonar[s] = 0;
    b.stiffen[s] = false;
    b.say_text[s][0] = '\0';
  }
  // pshared = 1: the other end may be another process.
  sem_init(&b.lockstep.motion_done, 1, 0);
  sem_init(&shm_->camera.frame_ready, 1, 0);
  sem_init(&shm_->camera.perception_done, 1, 0);
  shm_->camera.magic = al::kMagic;
  // The magic goes last: an agent that sees it sees an initialised block.
  std::atomic_thread_fence(std::memory_order_seq_cst);
  b.magic = al::kMagic;
  std::atomic_thread_fence(std::memory_order_seq_cst);
}

BodyHost::~BodyHost() {
  sem_destroy(&shm_->agent.lockstep.motion_done);
  sem_destroy(&shm_->camera.frame_ready);
  sem_destroy(&shm_->camera.perception_done);
  if (mode_ == Mode::InProcess) {
    sem_destroy(&tick_local_);
    return;
  }
  munmap(shm_, sizeof(al::SimRobotShm));
  shm_unlink(memory_name_.c_str());
  cleanup::unregister(memory_name_);
  sem_close(tick_);
  sem_unlink(semaphore_name_.c_str());
  cleanup::unregister(semaphore_name_);
}

al::AgentConnection BodyHost::connect() { return al::AgentConnection(&shm_->agent, tick_, &shm_->camera); }

bool BodyHost::publishSensors(const SensorValues& values, int64_t sim_time_us, int64_t tick) {
  al::AgentBlock& b = shm_->agent;
  const int slot = al::writerSlot(b.sensors_latest, b.sensors_read);
  b.sensors[slot] = values;
  b.lockstep.sim_time_us = sim_time_us;
  b.lockstep.tick = tick;
  b.sensors_latest.store(slot);

  int value = 0;
  sem_getvalue(tick_, &value);
  if (value <= 0) {
    sem_post(tick_);
    skipped_run_ = 0;
    if (contact_lost_) std::fprintf(stderr, "robot %s: contact regained at tick %lld\n", tag_.c_str(),
                                    static_cast<long long>(tick));
    contact_lost_ = false;
    return true;
  }
  // The program has not taken the last tick: like the DCM side, do not pile
  // up ticks; count the cycle as skipped.
  ++skipped_total_;
  ++skipped_run_;
  b.lockstep.skipped.fetch_add(1);
  if (skipped_run_ >= kContactLostCycles && !contact_lost_) {
    contact_lost_ = true;
    ++contact_lost_events_;
    std::fprintf(stderr, "robot %s: contact lost (%d cycles skipped) at tick %lld: sitting down\n", tag_.c_str(),
                 skipped_run_, static_cast<long long>(tick));
  }
  return false;
}

ActuatorCommand BodyHost::readActuators() {
  ActuatorCommand cmd;
  if (contact_lost_) {
    cmd.joints = agent::program::postureCommand(agent::program::Posture::Crouch);
    for (float& s : cmd.joints.stiffnesses) s = agent::program::kSafeSitStiffness;
    return cmd;
  }
  al::AgentBlock& b = shm_->agent;
  const int slot = al::claimLatest(b.actuators_latest, b.actuators_read);
  cmd.joints = b.joints[slot];
  cmd.leds = b.leds[slot];
  cmd.sonar = b.sonar[slot];
  cmd.stiffen = b.stiffen[slot];
  cmd.say.assign(b.say_text[slot], strnlen(b.say_text[slot], al::kSayTextLength));
  return cmd;
}

bool BodyHost::waitMotionDone(double timeout_s) { return waitWithTimeout(&shm_->agent.lockstep.motion_done, timeout_s); }

void BodyHost::publishFrame(const agent::libagent::CameraFrame& frame) {
  shm_->camera.frame = frame;
  sem_post(&shm_->camera.frame_ready);
}

bool BodyHost::waitPerceptionDone(double timeout_s) {
  return waitWithTimeout(&shm_->camera.perception_done, timeout_s);
}

void BodyHost::shutdown() {
  shm_->agent.lockstep.shutdown.store(1);
  shm_->camera.shutdown.store(1);
  sem_post(tick_);
  sem_post(&shm_->camera.frame_ready);
}

}  // namespace simswift::bridge
