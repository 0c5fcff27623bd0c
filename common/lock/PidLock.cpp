#include "common/lock/PidLock.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <thread>

namespace common::lock {

namespace {
int openLockFile(const std::string& path, mode_t mode) {
  int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, mode);
  if (fd >= 0) {
    struct stat st {};
    // Created now (mode as asked, whatever the umask), or ours already.
    if (::fstat(fd, &st) == 0 && st.st_uid == ::geteuid()) ::fchmod(fd, mode);
    return fd;
  }
  if (errno == EACCES) fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) throw LockError("cannot open the lock file " + path + ": " + std::strerror(errno));
  return fd;
}

// True if the file at `path` is still the one open at `fd` (not removed or
// replaced by a holder's removeAndRelease() while we waited for it).
bool samePath(int fd, const std::string& path) {
  struct stat a {}, b {};
  return ::fstat(fd, &a) == 0 && ::stat(path.c_str(), &b) == 0 && a.st_nlink > 0 && a.st_dev == b.st_dev &&
         a.st_ino == b.st_ino;
}

bool pidAlive(int pid) { return pid > 0 && (::kill(pid, 0) == 0 || errno == EPERM); }
}  // namespace

PidLock::PidLock(std::string path, mode_t mode) : path_(std::move(path)), fd_(openLockFile(path_, mode)) {}

PidLock::PidLock(PidLock&& o) noexcept : path_(std::move(o.path_)), fd_(o.fd_), locked_(o.locked_) {
  o.fd_ = -1;
  o.locked_ = false;
}

PidLock& PidLock::operator=(PidLock&& o) noexcept {
  if (this != &o) {
    if (fd_ >= 0) ::close(fd_);
    path_ = std::move(o.path_);
    fd_ = o.fd_;
    locked_ = o.locked_;
    o.fd_ = -1;
    o.locked_ = false;
  }
  return *this;
}

PidLock::~PidLock() {
  if (fd_ >= 0) ::close(fd_);
}

int PidLock::holderPid() const {
  char buf[32] = {};
  const ssize_t n = fd_ >= 0 ? ::pread(fd_, buf, sizeof buf - 1, 0) : 0;
  const int pid = n > 0 ? std::atoi(buf) : 0;
  return pid > 0 ? pid : 0;
}

bool PidLock::tryLock(double wait_s) {
  if (locked_) return true;
  // Wall clock: only how long to wait for a dying holder, never a result.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s);
  for (;;) {
    if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) {
      if (samePath(fd_, path_)) break;
      // Removed by the holder we waited for: the path's file now is another.
      ::close(fd_);
      fd_ = -1;
      fd_ = openLockFile(path_, 0644);
      continue;
    }
    const int err = errno;
    if (err == EINTR) continue;
    if (err != EWOULDBLOCK) throw LockError("cannot lock " + path_ + ": " + std::strerror(err));
    if (pidAlive(holderPid()) || std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  locked_ = true;
  const std::string me = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, me.data(), me.size(), 0) != static_cast<ssize_t>(me.size())) {
    // Read-only (another user's file) or full: the lock holds without the
    // pid; only a refused process's message lacks it.
  }
  return true;
}

void PidLock::removeAndRelease() {
  if (locked_) ::unlink(path_.c_str());
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  locked_ = false;
}

bool lockHeld(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;
  bool held = false;
  while (::flock(fd, LOCK_SH | LOCK_NB) != 0) {
    if (errno == EINTR) continue;
    held = errno == EWOULDBLOCK;
    break;
  }
  ::close(fd);  // releases the probe's shared lock
  return held;
}

}  // namespace common::lock
