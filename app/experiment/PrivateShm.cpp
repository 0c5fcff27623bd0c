#include "app/experiment/PrivateShm.hpp"

#include "sim/programs/MountNamespace.hpp"

#include <fcntl.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace simswift::experiment {

std::string enterPrivateShm() {
  const char* step = "";
  if (const int e = programs::enterOwnMountNamespace(programs::selfIdMaps(), &step))
    return std::string(step) + ": " + std::strerror(e);
  if (mount("simswift-trial", "/dev/shm", "tmpfs", MS_NOSUID | MS_NODEV, "mode=1777") != 0)
    return std::string("mount tmpfs on /dev/shm: ") + std::strerror(errno);
  return "";
}

bool privateShmAvailable(std::string* why) {
  // No namespace at all (or SIMSWIFT_MOUNT_NAMESPACE=off): no private /dev/shm.
  if (const programs::NamespaceSupport ns = programs::mountNamespaceSupport(); !ns.available) {
    if (why) *why = ns.why;
    return false;
  }
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
