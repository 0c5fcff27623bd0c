#include "sim/bridge/BodyHost.hpp"

#include <fcntl.h>
#include <sched.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <new>

#include "common/libagent/TripleBuffer.hpp"
#include "sim/bridge/AttachedProcesses.hpp"
#include "sim/bridge/ExtensionObject.hpp"
#include "sim/bridge/WaitStrategy.hpp"

namespace simswift::bridge {

namespace al = common::libagent;

namespace {
std::string sysError(const std::string& what) { return what + ": " + std::strerror(errno); }

// Opens (creating if needed) a 0600 shm object and sizes it to `size`.
// Returns the mapping; `fd_out` (if given) keeps the descriptor open.
void* openSized(const std::string& name, size_t size, int* fd_out = nullptr) {
  const int fd = shm_open(name.c_str(), O_CREAT | O_RDWR, 0600);
  if (fd < 0) throw BridgeError(sysError("shm_open " + name));
  fchmod(fd, 0600);  // independent of the umask
  struct stat st {};
  if (fstat(fd, &st) != 0 || static_cast<size_t>(st.st_size) != size) {
    // Empty (created by a program that started first) or another size (a
    // different build): size it. Pages past the old end read as zero.
    if (ftruncate(fd, static_cast<off_t>(size)) != 0) {
      const std::string e = sysError("ftruncate " + name);
      close(fd);
      throw BridgeError(e);
    }
  }
  void* p = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  if (p == MAP_FAILED) {
    const std::string e = sysError("mmap " + name);
    close(fd);
    throw BridgeError(e);
  }
  if (fd_out) *fd_out = fd;
  else close(fd);
  return p;
}

}  // namespace

BodyHost::BodyHost(int team, int player, Mode mode, const al::JointValues& initial, const BodyHostOptions& options)
    : BodySide(al::robotTag(team, player)),
      team_(team),
      player_(player),
      mode_(mode),
      options_(options),
      libagent_(options.start, options.release) {
  if (team < al::kMinTeamNumber || team > al::kMaxTeamNumber || player < al::kMinPlayer || player > al::kMaxPlayer)
    throw BridgeError("robot " + tag_ + ": the team must be an SPL team number " + std::to_string(al::kMinTeamNumber) +
                      ".." + std::to_string(al::kMaxTeamNumber) + " and the player " +
                      std::to_string(al::kMinPlayer) + ".." + std::to_string(al::kMaxPlayer));
  names_ = releaseNames(options.release, team, player, options.bare_names);
  if (mode == Mode::InProcess) {
    names_ = {"<in-process " + tag_ + ">", "", "", ""};
    own_block_.reset(new unsigned char[blockSize(options.release)]());  // zeroed
    own_ext_.reset(new SimExtension());
    raw_ = own_block_.get();
    ext_ = own_ext_.get();
    if (options.images) {
      own_images_.reset(new al::CameraImages());
      images_ = own_images_.get();
    }
    if (sem_init(&tick_local_, 0, 0) != 0) throw BridgeError(sysError("sem_init"));
    tick_ = &tick_local_;
  } else {
    setUpNamed();
  }
  initialise(initial);
}

// Takes the robot for this process, holding an flock on the extension object
// so that two simulators starting together cannot both take it.
void BodyHost::takeOwnership(int fd) {
  SimExtension& x = *ext_;
  const int old_pid = x.magic == al::kExtensionMagic ? x.simulator_pid.load() : 0;
  const uint64_t old_start = x.magic == al::kExtensionMagic ? x.simulator_start.load() : 0;
  if (old_pid != 0 && al::processAlive(old_pid, old_start)) {
    flock(fd, LOCK_UN);
    close(fd);
    munmap(ext_, sizeof(SimExtension));
    ext_ = nullptr;
    throw BridgeError("robot " + tag_ + ": " + names_.memory + " belongs to a running simswift (pid " +
                      std::to_string(old_pid) + "): stop that run first, or give this robot another team or player");
  }
  if (old_pid != 0)
    std::fprintf(stderr, "robot %s: taking over %s left by a killed run (simulator pid %d is gone)\n", tag_.c_str(),
                 names_.memory.c_str(), old_pid);
  x.magic = 0;  // until initialise() has finished
  x.simulator_pid.store(static_cast<int32_t>(getpid()));
  x.simulator_start.store(al::processStartTime(getpid()));
}

void BodyHost::setUpNamed() {
  int fd = -1;
  for (;;) {
    void* p = openSized(names_.extension, sizeof(SimExtension), &fd);
    ext_ = static_cast<SimExtension*>(p);
    if (flock(fd, LOCK_EX) != 0) {
      const std::string e = sysError("flock " + names_.extension);
      close(fd);
      munmap(p, sizeof(SimExtension));
      throw BridgeError(e);
    }
    // Removed as stale by another run while we waited for the lock: again.
    struct stat st {};
    if (fstat(fd, &st) == 0 && st.st_nlink > 0) break;
    close(fd);
    munmap(p, sizeof(SimExtension));
  }
  takeOwnership(fd);  // throws (leaving everything as it was) if a live simulator owns the robot
  cleanup::registerShm(names_.extension);
  named_set_up_ = true;
  try {
    // Created before any program waits for it: a 2016 program opens it
    // without O_CREAT, so it must exist first (as libagent's on a NAO).
    raw_ = openSized(names_.memory, blockSize(options_.release));
    cleanup::registerShm(names_.memory);
    sem_t* s = sem_open(names_.semaphore.c_str(), O_CREAT, 0600, 0);
    if (s == SEM_FAILED) throw BridgeError(sysError("sem_open " + names_.semaphore));
    cleanup::registerSem(names_.semaphore);
    tick_ = s;
    // A semaphore adopted from a program that started first, or left by a
    // killed run, may hold posts: start from 0.
    while (sem_trywait(tick_) == 0) {
    }
    if (options_.images) {
      images_ = static_cast<al::CameraImages*>(openSized(names_.images, sizeof(al::CameraImages)));
      cleanup::registerShm(names_.images);
    }
  } catch (...) {
    flock(fd, LOCK_UN);
    close(fd);
    releaseNamed();
    throw;
  }
  flock(fd, LOCK_UN);
  close(fd);
}

template <class F>
decltype(auto) BodyHost::withBlock(F&& f) {
  switch (options_.release) {
    case Release::R2016: return f(*static_cast<release::AgentData2016*>(raw_));
    case Release::R2018: return f(*static_cast<release::AgentData2018*>(raw_));
    case Release::R2017: break;
  }
  return f(*static_cast<release::AgentData2017*>(raw_));
}

template <class F>
decltype(auto) BodyHost::withBlock(F&& f) const {
  return const_cast<BodyHost*>(this)->withBlock(std::forward<F>(f));
}

bool BodyHost::standing() const {
  // The program writes this byte too: read as a byte (any value but 0 is
  // set), never as a bool that may hold something but 0 or 1.
  return withBlock([](auto& b) { return *reinterpret_cast<const volatile uint8_t*>(&b.standing) != 0; });
}

void BodyHost::initialise(const al::JointValues& initial) {
  if (options_.release == Release::R2017) block_ = static_cast<AgentData*>(raw_);
  withBlock([&](auto& b) {
    std::memset(static_cast<void*>(&b), 0, sizeof b);
    for (int s = 0; s < al::kSlots; ++s) b.joints[s] = initial;
    al::storeIndex(b.sensors_read, 0);
    al::storeIndex(b.sensors_latest, 0);
    al::storeIndex(b.actuators_read, 0);
    // Parked: no command yet (the program's first one unparks it).
    al::storeIndex(b.actuators_latest, al::kActuatorsParked);
    // Stiff start: `standing` until the program's first command (the
    // thesis's SimulationThread); limp start: clear, as libagent boots.
    b.standing = options_.start == StartMode::Stiff;
  });
  last_.joints = initial;
  for (int j = 0; j < al::kNumJoints; ++j) measured_[j] = initial.angles[j];

  // In this process the owner header is 0 (a new object); named, it holds this simulator.
  initialiseExtension(*ext_, sync_, images_);
  camera_ = CameraHandover(ext_);
}

void BodyHost::releaseNamed() {
  if (!named_set_up_) return;
  named_set_up_ = false;
  if (images_) munmap(images_, sizeof(al::CameraImages));
  if (raw_) munmap(raw_, blockSize(options_.release));
  if (ext_) munmap(ext_, sizeof(SimExtension));
  if (tick_) sem_close(tick_);
  images_ = nullptr;
  raw_ = nullptr;
  block_ = nullptr;
  ext_ = nullptr;
  tick_ = nullptr;
  for (const std::string& n : {names_.images, names_.memory, names_.extension}) {
    shm_unlink(n.c_str());
    cleanup::unregister(n);
  }
  sem_unlink(names_.semaphore.c_str());
  cleanup::unregister(names_.semaphore);
}

BodyHost::~BodyHost() {
  if (ext_) destroyExtension(*ext_);
  if (mode_ == Mode::InProcess) {
    sem_destroy(&tick_local_);
    return;
  }
  releaseNamed();
}

al::AgentConnection BodyHost::connect() {
  if (!block_)
    throw BridgeError("robot " + tag_ + ": an in-process robot program speaks the 2017 block; release " +
                      std::to_string(releaseYear(options_.release)) + " needs an external program");
  return al::AgentConnection(block_, tick_, ext_);
}

void BodyHost::setSync(SyncMode mode) {
  sync_ = mode;
  ext_->sync_mode.store(static_cast<int32_t>(mode));
}

bool BodyHost::publishSensors(const SensorValues& values, int64_t sim_time_us, int64_t tick) {
  LibagentBehaviour::Standing standing;
  const al::ButtonPresses pressed = libagent_.onSensors(values, standing);
  for (const std::string& m : libagent_.takeLog())
    std::fprintf(stderr, "robot %s: libagent: %s (tick %lld)\n", tag_.c_str(), m.c_str(), static_cast<long long>(tick));
  for (int j = 0; j < al::kNumJoints; ++j) measured_[j] = values.joints.angles[j];
  withBlock([&](auto& b) {
    const int slot = al::writerSlot(b.sensors_latest, b.sensors_read);
    b.sensors[slot] = values;
    b.buttons[slot] = pressed;
    ext_->slot_time_us[slot] = sim_time_us;
    ext_->slot_tick[slot] = tick;
    if (standing.write) b.standing = *standing.write;
    al::storeIndex(b.sensors_latest, static_cast<uint8_t>(slot));
  });

  int value = 0;
  sem_getvalue(tick_, &value);
  if (value <= 0) {
    sem_post(tick_);
    if (contact_lost_)
      std::fprintf(stderr, "robot %s: contact regained at tick %lld\n", tag_.c_str(), static_cast<long long>(tick));
    skipped_run_ = 0;
    contact_lost_ = false;
    return true;
  }
  // The program has not taken the last tick: like the DCM side, do not pile
  // up ticks; count the cycle as skipped.
  ++skipped_total_;
  ++skipped_run_;
  ext_->skipped.fetch_add(1);
  if (skipped_run_ > kContactLostCycles && !contact_lost_) {
    contact_lost_ = true;
    ++contact_lost_events_;
    std::fprintf(stderr, "robot %s: contact lost (%d cycles skipped) at tick %lld: sitting down\n", tag_.c_str(),
                 skipped_run_, static_cast<long long>(tick));
  }
  return false;
}

bool BodyHost::answered() const {
  return withBlock([](auto& b) { return al::validSlot(al::loadIndex(b.actuators_latest)); });
}

bool BodyHost::waitAnswer(double timeout_s) {
  return waitFor([this] { return answered(); },
                 [this]() -> sem_t* { return clientAnnounced() ? &ext_->answered : nullptr; }, timeout_s);
}

ActuatorCommand BodyHost::readActuators() {
  // The program may write any byte of the block at any time: the slot is
  // the one value claimLatest() read and checked, never a second load.
  LibagentBehaviour::Standing set_standing;
  const bool read = withBlock([&](auto& b) {
    using Block = std::decay_t<decltype(b)>;
    const int slot = al::claimLatest(b.actuators_latest, b.actuators_read);
    if (!al::validSlot(slot)) return false;  // no answer (parked), or a byte no slot has
    last_.joints = b.joints[slot];
    last_.leds = b.leds[slot];
    last_.sonar = b.sonar[slot];
    last_.stiffen = false;
    if constexpr (release::hasStiffen<Block>()) {
      // Acted on once, then NONE in its slot (libagent's postCallback).
      last_.stiffen = b.stiffen[slot] == al::STIFFEN;
      if (last_.stiffen) libagent_.stiffen(set_standing);
      b.stiffen[slot] = al::NONE;
    }
    last_.say.assign(b.sayTexts[slot], strnlen(b.sayTexts[slot], release::sayLength<Block>()));
    if (set_standing.write) b.standing = *set_standing.write;
    // Lock-step: consumed; the next valid index is the next answer.
    if (sync_ == SyncMode::LockStep) al::storeIndex(b.actuators_latest, al::kActuatorsParked);
    return true;
  });
  if (read) {
    commanded_ = true;
    ++commands_read_;
  }
  // What the body gets: the program's command, or libagent's own (limp,
  // `standing`, the sit after a contact loss).
  ActuatorCommand out = last_;
  out.joints = libagent_.body(last_.joints, commanded_, standing(), contact_lost_, measured_.data());
  for (const std::string& m : libagent_.takeLog()) std::fprintf(stderr, "robot %s: libagent: %s\n", tag_.c_str(), m.c_str());
  return out;
}

void BodyHost::publishFrame(const al::CameraFrame& frame) { camera_.publish(frame); }

bool BodyHost::waitPerceptionDone(double timeout_s) { return camera_.waitDone(timeout_s); }

void BodyHost::shutdown() {
  ext_->shutdown.store(1);
  // A simswift-aware program (AgentConnection) is woken and reads the
  // shutdown flag. An unchanged libagent program is not: woken, it would
  // re-read the last sensor slot as if a new cycle had come. It stays in
  // sem_wait on a semaphore this run unlinks, so it can never attach to the
  // next run: name it, so the user stops it (libagent itself kills the
  // robot program when it unloads).
  if (mode_ == Mode::InProcess || clientAnnounced()) {
    int value = 0;
    sem_getvalue(tick_, &value);
    if (value <= 0) sem_post(tick_);
  } else {
    for (const AttachedProcess& p : processesMapping(names_.memory))
      std::fprintf(stderr,
                   "robot %s: program %s (pid %d) is still attached to %s; it will wait for a cycle that never "
                   "comes: stop it before the next run\n",
                   tag_.c_str(), p.name.c_str(), p.pid, names_.memory.c_str());
  }
  camera_.shutdown();
}

std::string BodyHost::attachHint() const {
  const std::string robot = "--team " + std::to_string(team_) + " --player " + std::to_string(player_);
  return "start its libagent robot program, in the robot's view with its clock and cameras: `simswift attach " +
         robot + " -- PROGRAM` (or `simswift-agent " + robot + (options_.bare_names ? " --bare" : "") + "`)";
}

// The release's N is the memory name's digits (none for the bare names).
std::map<std::string, std::string> BodyHost::placeholders() const {
  return {{"number", names_.memory.substr(std::string(al::kMemoryName).size())},
          {"memory", names_.memory},
          {"semaphore", names_.semaphore},
          {"extension", names_.extension}};
}

}  // namespace simswift::bridge
