#include "sim/experiment/PrivateShm.hpp"

#include <fcntl.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace simswift::experiment {

namespace {

bool writeFile(const char* path, const std::string& text) {
  const int fd = open(path, O_WRONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  close(fd);
  return ok;
}

}  // namespace

std::string enterPrivateShm() {
  const uid_t uid = geteuid();
  const gid_t gid = getegid();
  if (uid != 0 || unshare(CLONE_NEWNS) != 0) {
    // Not root (or not allowed): a user namespace first, mapping us to ourselves.
    if (unshare(CLONE_NEWUSER | CLONE_NEWNS) != 0)
      return std::string("unshare(user + mount namespace): ") + std::strerror(errno);
    writeFile("/proc/self/setgroups", "deny");
    if (!writeFile("/proc/self/uid_map", std::to_string(uid) + " " + std::to_string(uid) + " 1\n") ||
        !writeFile("/proc/self/gid_map", std::to_string(gid) + " " + std::to_string(gid) + " 1\n"))
      return std::string("uid_map/gid_map: ") + std::strerror(errno);
  }
  // Our mounts stay ours (not propagated back to the machine).
  if (mount("none", "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0)
    return std::string("mount --make-rprivate /: ") + std::strerror(errno);
  if (mount("simswift-trial", "/dev/shm", "tmpfs", MS_NOSUID | MS_NODEV, "mode=1777") != 0)
    return std::string("mount tmpfs on /dev/shm: ") + std::strerror(errno);
  return "";
}

bool privateShmAvailable(std::string* why) {
  int pipefd[2];
  if (pipe(pipefd) != 0) {
    if (why) *why = std::strerror(errno);
    return false;
  }
  const pid_t pid = fork();
  if (pid == 0) {
    close(pipefd[0]);
    const std::string err = enterPrivateShm();
    if (!err.empty()) {
      ssize_t w = write(pipefd[1], err.data(), err.size());
      (void)w;
    }
    _exit(err.empty() ? 0 : 1);
  }
  close(pipefd[1]);
  if (pid < 0) {
    close(pipefd[0]);
    if (why) *why = std::strerror(errno);
    return false;
  }
  char buf[512];
  ssize_t n = 0, got;
  while ((got = read(pipefd[0], buf + n, sizeof buf - 1 - static_cast<size_t>(n))) > 0) n += got;
  close(pipefd[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (why) *why = std::string(buf, static_cast<size_t>(n));
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace simswift::experiment
