#include "sim/bridge/V4l2Devices.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <new>

#include "sim/bridge/BodyHost.hpp"  // BridgeError
#include "sim/bridge/Cleanup.hpp"

namespace simswift::bridge {

namespace cv = common::v4l2;

namespace {

std::string errnoMessage(const std::string& what) { return what + ": " + std::strerror(errno); }

// The FIFO's name as a shared-memory name ("/simswift-v4l2-...-top"), for
// cleanup's registry (shm_unlink removes any file in /dev/shm).
std::string fifoShmName(const std::string& block, const char* which) { return block + "-" + which; }

// A FIFO at `path`, made afresh (a killed run's is replaced), 0600.
void makeFifo(const std::string& path) {
  ::unlink(path.c_str());
  if (::mkfifo(path.c_str(), 0600) != 0) throw BridgeError(errnoMessage("mkfifo " + path));
}

int openFifo(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw BridgeError(errnoMessage("open " + path));
  return fd;
}

// Everything in the FIFO read (never blocks: O_NONBLOCK).
void drain(int fd) {
  char buffer[256];
  while (::read(fd, buffer, sizeof buffer) > 0) {
  }
}

}  // namespace

V4l2Devices::V4l2Devices(const std::string& tag, const std::array<std::string, cv::kNumCameras>& device,
                         const std::string& name)
    : tag_(tag), name_(!name.empty() ? name : "/simswift-v4l2-p" + std::to_string(::getpid()) + "-" + tag) {
  for (const std::string& d : device)
    if (d.empty() || d.size() >= static_cast<size_t>(cv::kMaxDevicePath))
      throw BridgeError("robot " + tag_ + ": camera device path '" + d + "' must have 1.." +
                        std::to_string(cv::kMaxDevicePath - 1) + " characters");
  ::shm_unlink(name_.c_str());
  const int fd = ::shm_open(name_.c_str(), O_CREAT | O_EXCL | O_RDWR | O_CLOEXEC, 0600);
  if (fd < 0) throw BridgeError(errnoMessage("robot " + tag_ + ": shm_open " + name_));
  if (::ftruncate(fd, sizeof(cv::DeviceBlock)) != 0) {
    const std::string e = errnoMessage("robot " + tag_ + ": ftruncate " + name_);
    ::close(fd);
    ::shm_unlink(name_.c_str());
    throw BridgeError(e);
  }
  void* p = ::mmap(nullptr, sizeof(cv::DeviceBlock), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  ::close(fd);
  if (p == MAP_FAILED) {
    const std::string e = errnoMessage("robot " + tag_ + ": mmap " + name_);
    ::shm_unlink(name_.c_str());
    throw BridgeError(e);
  }
  // A fresh object reads as zero; the header and each channel's fields set,
  // the magic last (a shim that sees it sees a set-up block).
  // The block and its FIFOs (files in /dev/shm: shm_unlink removes them too)
  // go however the run ends.
  cleanup::registerShm(name_);
  for (const char* which : {cv::cameraFifo(0), cv::cameraFifo(1), cv::kTakenFifo})
    cleanup::registerShm(fifoShmName(name_, which));
  block_ = static_cast<cv::DeviceBlock*>(p);
  block_->version = cv::kBlockVersion;
  for (int c = 0; c < cv::kNumCameras; ++c) {
    cv::CameraChannel& ch = block_->camera[c];
    std::strncpy(ch.device, device[c].c_str(), sizeof ch.device - 1);
    ch.width_wanted.store(cv::kDefaultFrameSize.width);
    ch.height_wanted.store(cv::kDefaultFrameSize.height);
  }
  try {
    for (int c = 0; c < cv::kNumCameras; ++c) {
      const std::string path = cv::fifoPath(name_, cv::cameraFifo(c));
      makeFifo(path);
      ready_[c] = openFifo(path, O_RDWR);
    }
    const std::string taken = cv::fifoPath(name_, cv::kTakenFifo);
    makeFifo(taken);
    taken_ = openFifo(taken, O_RDONLY);
  } catch (...) {
    release();  // a destructor does not run for a constructor that throws
    throw;
  }
  block_->magic.store(cv::kBlockMagic, std::memory_order_release);
}

V4l2Devices::~V4l2Devices() { release(); }

void V4l2Devices::release() {
  for (int& fd : ready_)
    if (fd >= 0) ::close(fd), fd = -1;
  if (taken_ >= 0) ::close(taken_), taken_ = -1;
  for (const char* which : {cv::cameraFifo(0), cv::cameraFifo(1), cv::kTakenFifo}) {
    ::unlink(cv::fifoPath(name_, which).c_str());
    cleanup::unregister(fifoShmName(name_, which));
  }
  if (block_) {
    ::munmap(block_, sizeof(cv::DeviceBlock));
    block_ = nullptr;
  }
  ::shm_unlink(name_.c_str());
  cleanup::unregister(name_);
}

void V4l2Devices::remove(const std::string& name) {
  for (const char* which : {cv::cameraFifo(0), cv::cameraFifo(1), cv::kTakenFifo})
    ::unlink(cv::fifoPath(name, which).c_str());
  ::shm_unlink(name.c_str());
}

bool V4l2Devices::served(const std::string& name) {
  const int fd = ::shm_open(name.c_str(), O_RDONLY | O_CLOEXEC, 0);
  if (fd < 0) return false;
  struct stat st {};
  bool set_up = false;
  if (::fstat(fd, &st) == 0 && static_cast<size_t>(st.st_size) >= sizeof(cv::DeviceBlock)) {
    void* p = ::mmap(nullptr, sizeof(cv::DeviceBlock), PROT_READ, MAP_SHARED, fd, 0);
    if (p != MAP_FAILED) {
      const auto* b = static_cast<const cv::DeviceBlock*>(p);
      set_up = b->magic.load(std::memory_order_acquire) == cv::kBlockMagic && b->version == cv::kBlockVersion;
      ::munmap(p, sizeof(cv::DeviceBlock));
    }
  }
  ::close(fd);
  if (!set_up) return false;
  // A write end opened without blocking fails (ENXIO) when no process has
  // the FIFO open for reading: the simulator's read-write end is gone. The
  // simulator keeps a writer too, so closing this one hangs nobody up.
  const int w = ::open(cv::fifoPath(name, cv::cameraFifo(0)).c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
  if (w < 0) return false;
  ::close(w);
  return true;
}

std::vector<std::string> V4l2Devices::removeStale(const std::string& tag) {
  std::vector<std::string> removed;
  DIR* d = ::opendir("/dev/shm");
  if (!d) return removed;
  std::vector<std::string> blocks;
  const std::string prefix = "simswift-v4l2-";
  while (dirent* e = ::readdir(d)) {
    const std::string file = e->d_name;
    if (file.compare(0, prefix.size(), prefix) != 0) continue;
    // A block, not one of its FIFOs; one robot's: "...-<tag>" (a launched
    // program's "simswift-v4l2-p<pid>-<tag>" or an external robot's).
    struct stat st {};
    if (::stat(("/dev/shm/" + file).c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    if (!tag.empty() && (file.size() < tag.size() + 1 || file.compare(file.size() - tag.size() - 1, std::string::npos,
                                                                     "-" + tag) != 0))
      continue;
    blocks.push_back("/" + file);
  }
  ::closedir(d);
  for (const std::string& b : blocks) {
    if (served(b)) continue;
    remove(b);
    removed.push_back(b);
  }
  return removed;
}

void V4l2Devices::corrupt(int c, const std::string& what) const {
  throw BridgeError("robot " + tag_ + ": its program wrote " + what + " into camera " + cv::cameraFifo(c) +
                    "'s V4L2 block " + name_ + " (no simswift shim writes that: a corrupt block)");
}

std::array<V4l2Devices::Request, cv::kNumCameras> V4l2Devices::requests() {
  std::array<Request, cv::kNumCameras> out;
  for (int c = 0; c < cv::kNumCameras; ++c) {
    cv::CameraChannel& ch = block_->camera[c];
    // Each field once (the program may change it meanwhile), then checked.
    const int32_t streaming = ch.streaming.load(std::memory_order_acquire);
    const int32_t queued = ch.buffers_queued.load(std::memory_order_acquire);
    const int32_t w = ch.width_wanted.load(std::memory_order_acquire);
    const int32_t h = ch.height_wanted.load(std::memory_order_acquire);
    if (streaming != 0 && streaming != 1) corrupt(c, "streaming = " + std::to_string(streaming));
    if (queued < 0 || queued > cv::kMaxBuffers) corrupt(c, "buffers_queued = " + std::to_string(queued));
    if (!cv::isFrameSize(w, h)) corrupt(c, "a format of " + std::to_string(w) + "x" + std::to_string(h));
    out[c].publish = streaming == 1 && queued > 0;
    out[c].size = {w, h};
  }
  return out;
}

void V4l2Devices::publish(int c, int64_t frame, int64_t t_us, common::libagent::ImageSize size) {
  cv::CameraChannel& ch = block_->camera[c];
  ch.frame_index = frame;
  ch.sim_time_us = t_us;
  ch.width = size.width;
  ch.height = size.height;
  ch.frames_posted.store(++posted_[c], std::memory_order_release);
  waiting_[c] = true;
  const char byte = 1;
  // Readiness for the program's poll; a full FIFO (a program that never
  // reads it) is already readable.
  ssize_t n = ::write(ready_[c], &byte, 1);
  (void)n;
}

bool V4l2Devices::allTaken() {
  bool all = true;
  for (int c = 0; c < cv::kNumCameras; ++c) {
    if (!waiting_[c]) continue;
    cv::CameraChannel& ch = block_->camera[c];
    const int64_t taken = ch.frames_taken.load(std::memory_order_acquire);
    const int32_t streaming = ch.streaming.load(std::memory_order_acquire);
    if (taken < taken_seen_[c] || taken > posted_[c])
      corrupt(c, "frames_taken = " + std::to_string(taken) + " (was " + std::to_string(taken_seen_[c]) +
                     ", frames published " + std::to_string(posted_[c]) + ")");
    taken_seen_[c] = taken;
    if (taken == posted_[c] || streaming == 0) waiting_[c] = false;
    else all = false;
  }
  return all;
}

bool V4l2Devices::waitTaken(double timeout_s) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(timeout_s);
  for (;;) {
    if (allTaken()) return true;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    pollfd p{taken_, POLLIN, 0};
    const int r = ::poll(&p, 1, static_cast<int>(left));
    if (r > 0 && (p.revents & POLLIN)) drain(taken_);
    if (r > 0 && (p.revents & POLLHUP) && !(p.revents & POLLIN)) {
      // Every process that held the cameras has closed them (ended): they
      // stream no more. The read end reopened, so that the next program's
      // hang-up is seen again.
      for (cv::CameraChannel& ch : block_->camera) {
        ch.streaming.store(0);
        ch.buffers_queued.store(0);
      }
      ::close(taken_);
      taken_ = openFifo(cv::fifoPath(name_, cv::kTakenFifo), O_RDONLY);
    }
  }
}

void V4l2Devices::shutdown() {
  if (!block_) return;
  block_->shutdown.store(1, std::memory_order_release);
  const char byte = 1;
  for (int fd : ready_) {
    ssize_t n = ::write(fd, &byte, 1);
    (void)n;
  }
}

}  // namespace simswift::bridge
