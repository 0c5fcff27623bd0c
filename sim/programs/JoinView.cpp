#include "sim/programs/JoinView.hpp"

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

#include "common/clock/ClockPage.hpp"

namespace simswift::programs {

namespace cc = common::clock;

std::optional<RunPage> readRunPage(const std::string& name) {
  const int fd = shm_open(name.c_str(), O_RDONLY | O_CLOEXEC, 0);
  if (fd < 0) return std::nullopt;
  struct stat st {};
  std::optional<RunPage> out;
  // Only a page of this user's own run: the page names a folder and a
  // process this command is then started in.
  if (fstat(fd, &st) == 0 && st.st_uid == geteuid() && static_cast<size_t>(st.st_size) >= sizeof(cc::ClockLayout)) {
    void* p = mmap(nullptr, sizeof(cc::ClockLayout), PROT_READ, MAP_SHARED, fd, 0);
    if (p != MAP_FAILED) {
      const auto* page = static_cast<const volatile cc::ClockLayout*>(p);
      if (page->magic == cc::kMagic) {
        std::atomic_thread_fence(std::memory_order_acquire);  // the magic seen: the header is
        const pid_t run = page->run_pid;
        // The run alive (EPERM: another user's, alive all the same).
        if (page->version == cc::kVersion && page->size == sizeof(cc::ClockLayout) && run > 0 &&
            (kill(run, 0) == 0 || errno == EPERM)) {
          RunPage r;
          r.flags = page->flags;
          r.tick_ns = page->tick_ns;
          if (r.flags & cc::kFlagView) {
            r.view_pid = page->view_pid;
            char folder[sizeof(cc::ClockLayout::view_folder)];
            for (size_t i = 0; i < sizeof folder; ++i) folder[i] = page->view_folder[i];
            folder[sizeof folder - 1] = '\0';
            r.view_folder = folder;
          }
          // A view is named by a live process and an absolute folder, or not taken.
          if (!(r.flags & cc::kFlagView) || (r.view_pid > 0 && !r.view_folder.empty() && r.view_folder[0] == '/'))
            out = r;
        }
      }
      munmap(p, sizeof(cc::ClockLayout));
    }
  }
  close(fd);
  return out;
}

std::string enterViewNamespaces(int view_pid) {
  const std::string base = "/proc/" + std::to_string(view_pid) + "/ns/";
  struct Space {
    const char* name;
    int type;
    int fd;
  } spaces[] = {{"user", CLONE_NEWUSER, -1}, {"net", CLONE_NEWNET, -1}, {"pid", CLONE_NEWPID, -1}};
  const auto closeAll = [&] {
    for (Space& s : spaces)
      if (s.fd >= 0) close(s.fd), s.fd = -1;
  };
  // All opened and compared first: /proc is the machine's until the first
  // setns. One the view shares with the caller is not entered (a user
  // namespace when simswift is root, the network where the machine gives
  // the robot none of its own): a process may not re-enter its own user
  // namespace, nor (unprivileged) the machine's network.
  bool same[3] = {};
  for (size_t i = 0; i < 3; ++i) {
    Space& s = spaces[i];
    s.fd = open((base + s.name).c_str(), O_RDONLY | O_CLOEXEC);
    if (s.fd < 0) {
      const std::string why = base + s.name + ": " + std::strerror(errno);
      closeAll();
      return "cannot open the robot's view (" + why + "; the run has ended, or is another user's)";
    }
    struct stat theirs {}, ours {};
    same[i] = fstat(s.fd, &theirs) == 0 && stat(("/proc/self/ns/" + std::string(s.name)).c_str(), &ours) == 0 &&
              theirs.st_ino == ours.st_ino && theirs.st_dev == ours.st_dev;
  }
  for (size_t i = 0; i < 3; ++i) {
    Space& s = spaces[i];
    if (same[i]) continue;
    if (setns(s.fd, s.type) != 0) {
      const std::string why = std::string("setns(") + s.name + " namespace of the robot's view): " + std::strerror(errno);
      closeAll();
      return why;
    }
  }
  closeAll();
  return "";
}

std::vector<MountOp> joinedMounts(const std::string& folder, const std::string& robocup_socket,
                                  const std::vector<std::string>& named) {
  ProgramView view;
  view.isolate = true;
  view.folder = folder;
  view.robocup_socket = robocup_socket;
  view.carry = pathsUnderTmp(named);
  view.files = defaultFiles();  // an external robot's: the defaults (Programs::makeExternal)
  return planView(view, /*prepare=*/false);
}

int enterJoinedMounts(const std::vector<MountOp>& mounts, const char** what) {
  if (unshare(CLONE_NEWNS) != 0) {
    *what = "unshare(mount namespace)";
    return errno;
  }
  if (mount("none", "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) {
    *what = "mount --make-rprivate /";
    return errno;
  }
  size_t failed = 0;
  if (const int e = applyView(mounts, &failed)) {
    *what = failed < mounts.size() ? mounts[failed].what.c_str() : "a mount";
    return e;
  }
  return 0;
}

}  // namespace simswift::programs
