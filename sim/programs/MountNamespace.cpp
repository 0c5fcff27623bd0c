#include "sim/programs/MountNamespace.hpp"

#include <fcntl.h>
#include <sched.h>
#include <sys/mount.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

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

}  // namespace simswift::programs
