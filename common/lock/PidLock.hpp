// An exclusive flock on a lock file that holds the holder's pid: how a
// process says "this is mine while I live" about a path, and how anyone
// asks whether it still is without disturbing the holder. A results folder
// (app/experiment, dir/.lock) and a LoLA socket (sim/lola, <socket>.lock)
// are claimed with it.
//
// The kernel releases an flock when the last descriptor holding it closes,
// so a killed holder never leaves a lock behind; the pid is only for
// messages ("in use by pid N") and to tell a live holder from one whose
// forked children still hold the descriptor.
#pragma once

#include <sys/types.h>

#include <stdexcept>
#include <string>

namespace common::lock {

struct LockError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class PidLock {
 public:
  PidLock() = default;
  // Opens (creating with `mode`, set explicitly, umask or not) the lock file
  // at `path`. A file another user created is opened read-only (an flock
  // needs no write access; the pid is then not written). Throws LockError
  // naming the path if it cannot be opened.
  explicit PidLock(std::string path, mode_t mode = 0644);
  PidLock(PidLock&& o) noexcept;
  PidLock& operator=(PidLock&& o) noexcept;
  PidLock(const PidLock&) = delete;
  PidLock& operator=(const PidLock&) = delete;
  ~PidLock();  // releases the lock (if no forked child holds a copy of the descriptor)

  // Takes the lock without blocking and writes this process's pid into the
  // file. A holder whose pid is gone (its children still hold the lock, or
  // a prober holds it for an instant) is waited for up to `wait_s` seconds
  // of wall-clock time. false: a live process holds it (holderPid() says
  // which) or the wait ran out; throws LockError on any other error.
  bool tryLock(double wait_s);
  bool locked() const { return locked_; }
  // The pid the holder wrote (0 if none or unreadable).
  int holderPid() const;
  const std::string& path() const { return path_; }
  // Removes the lock file while still holding the lock (a process that
  // opened it before then sees it unlinked and opens it again), then
  // releases it. Only for a file nobody else should find again.
  void removeAndRelease();

 private:
  std::string path_;
  int fd_ = -1;
  bool locked_ = false;
};

// True if a process holds the lock at `path`. Probes with a shared lock for
// an instant: never touches what the holder guards (a socket's connection).
// A missing file is not held.
bool lockHeld(const std::string& path);

}  // namespace common::lock
