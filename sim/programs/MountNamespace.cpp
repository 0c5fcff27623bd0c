#include "sim/programs/MountNamespace.hpp"

#include <fcntl.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace simswift::programs {

namespace {

// Writes `text` to a /proc file. False on failure.
bool writeProc(const char* path, const char* text) {
  const int fd = open(path, O_WRONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const ssize_t n = static_cast<ssize_t>(std::strlen(text));
  const bool ok = write(fd, text, static_cast<size_t>(n)) == n;
  close(fd);
  return ok;
}

}  // namespace

IdMaps selfIdMaps() {
  IdMaps m{};
  std::snprintf(m.uid, sizeof m.uid, "%u %u 1\n", static_cast<unsigned>(geteuid()), static_cast<unsigned>(geteuid()));
  std::snprintf(m.gid, sizeof m.gid, "%u %u 1\n", static_cast<unsigned>(getegid()), static_cast<unsigned>(getegid()));
  return m;
}

int enterOwnMountNamespace(const IdMaps& maps, const char** step) {
  auto fail = [&](const char* what, int err) {
    if (step) *step = what;
    return err;
  };
  if (geteuid() != 0 || unshare(CLONE_NEWNS) != 0) {
    if (unshare(CLONE_NEWUSER | CLONE_NEWNS) != 0) return fail("unshare(user + mount namespace)", errno);
    writeProc("/proc/self/setgroups", "deny");
    errno = 0;
    if (!writeProc("/proc/self/uid_map", maps.uid) || !writeProc("/proc/self/gid_map", maps.gid))
      return fail("uid_map/gid_map", errno != 0 ? errno : EIO);  // a short write sets none
  }
  if (mount("none", "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return fail("mount --make-rprivate /", errno);
  return 0;
}

int enterMountNamespaceInNewUser(const IdMaps& maps, const char** step) {
  auto fail = [&](const char* what, int err) {
    if (step) *step = what;
    return err;
  };
  writeProc("/proc/self/setgroups", "deny");
  errno = 0;
  if (!writeProc("/proc/self/uid_map", maps.uid) || !writeProc("/proc/self/gid_map", maps.gid))
    return fail("uid_map/gid_map", errno != 0 ? errno : EIO);
  if (unshare(CLONE_NEWNS) != 0) return fail("unshare(mount namespace)", errno);
  if (mount("none", "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return fail("mount --make-rprivate /", errno);
  return 0;
}

// The probe: a child tries and writes into a pipe its errno, then the name
// of the step that failed (the attempt's own words); a child that writes
// nothing (killed) counts as no.
NamespaceSupport probeInChild(int (*attempt)(const IdMaps& maps, const char** step)) {
  const IdMaps maps = selfIdMaps();
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return {false, std::string("pipe: ") + std::strerror(errno)};
  const pid_t pid = fork();
  if (pid < 0) {
    const int e = errno;
    close(fds[0]), close(fds[1]);
    return {false, std::string("fork: ") + std::strerror(e)};
  }
  if (pid == 0) {
    const char* step = "";
    char report[128] = {};
    const int err = attempt(maps, &step);
    std::memcpy(report, &err, sizeof err);
    std::strncpy(report + sizeof err, step ? step : "", sizeof report - sizeof err - 1);
    ssize_t w = write(fds[1], report, sizeof report);
    (void)w;
    _exit(0);
  }
  close(fds[1]);
  char report[128] = {};
  ssize_t n;
  do n = read(fds[0], report, sizeof report);
  while (n < 0 && errno == EINTR);
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (n != static_cast<ssize_t>(sizeof report)) return {false, "the probe's child gave no answer"};
  int err = 0;
  std::memcpy(&err, report, sizeof err);
  if (err == 0) return {true, ""};
  report[sizeof report - 1] = '\0';
  return {false, std::string(report + sizeof err) + ": " + std::strerror(err)};
}


NamespaceSupport mountNamespaceSupport() {
  const char* forced = std::getenv("SIMSWIFT_MOUNT_NAMESPACE");
  if (forced && std::strcmp(forced, "off") == 0) return {false, "SIMSWIFT_MOUNT_NAMESPACE=off"};
  static std::once_flag once;
  static NamespaceSupport probed;
  std::call_once(once, [] { probed = probeInChild(enterOwnMountNamespace); });
  return probed;
}

}  // namespace simswift::programs
