// Objects a killed simulator left in /dev/shm: found by their extension
// object, whose owner pid (and start time) no longer runs.
#include <dirent.h>
#include <fcntl.h>
#include <semaphore.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>

#include "sim/bridge/StaleObjects.hpp"

#include "common/libagent/SharedNames.hpp"
#include "common/libagent/SimExtension.hpp"

namespace simswift::bridge {

namespace al = common::libagent;

namespace {
// The suffix of an extension object's file name ("" for the bare names), or
// false if `file` is not one.
bool extensionSuffix(const std::string& file, std::string* suffix) {
  const std::string prefix = std::string(al::kExtensionName).substr(1);  // no leading '/'
  if (file.compare(0, prefix.size(), prefix) != 0) return false;
  *suffix = file.substr(prefix.size());
  return std::all_of(suffix->begin(), suffix->end(), [](unsigned char c) { return std::isdigit(c); });
}

// If the extension `name` belongs to a simulator that is gone, returns its
// descriptor, exclusively locked (a simulator setting the robot up holds the
// same lock), and the pid; else -1 (owned by a live simulator, being set up,
// no owner yet, or unreadable).
int lockIfOwnerGone(const std::string& name, int* pid) {
  const int fd = shm_open(name.c_str(), O_RDONLY, 0);
  if (fd < 0) return -1;
  bool gone = false;
  struct stat st {};
  if (flock(fd, LOCK_EX | LOCK_NB) == 0 && fstat(fd, &st) == 0 &&
      static_cast<size_t>(st.st_size) >= sizeof(al::SimExtension)) {
    void* p = mmap(nullptr, sizeof(al::SimExtension), PROT_READ, MAP_SHARED, fd, 0);
    if (p != MAP_FAILED) {
      const auto* x = static_cast<const al::SimExtension*>(p);
      *pid = x->simulator_pid.load();
      gone = x->magic == al::kExtensionMagic && *pid != 0 && !al::processAlive(*pid, x->simulator_start.load());
      munmap(p, sizeof(al::SimExtension));
    }
  }
  if (gone) return fd;
  close(fd);  // also releases the lock
  return -1;
}
}  // namespace

namespace {
// Suffixes of every simswift extension object in /dev/shm.
std::vector<std::string> extensionSuffixes() {
  std::vector<std::string> suffixes;
  DIR* d = opendir("/dev/shm");
  if (!d) return suffixes;
  while (dirent* e = readdir(d)) {
    std::string suffix;
    if (extensionSuffix(e->d_name, &suffix)) suffixes.push_back(suffix);
  }
  closedir(d);
  std::sort(suffixes.begin(), suffixes.end());
  return suffixes;
}
}  // namespace

std::vector<LiveRobot> liveRobots() {
  std::vector<LiveRobot> live;
  for (const std::string& suffix : extensionSuffixes()) {
    const al::RobotNames n = al::namesWithSuffix(suffix);
    const int fd = shm_open(n.extension.c_str(), O_RDONLY, 0);
    if (fd < 0) continue;
    struct stat st {};
    if (fstat(fd, &st) == 0 && static_cast<size_t>(st.st_size) >= sizeof(al::SimExtension)) {
      void* p = mmap(nullptr, sizeof(al::SimExtension), PROT_READ, MAP_SHARED, fd, 0);
      if (p != MAP_FAILED) {
        const auto* x = static_cast<const al::SimExtension*>(p);
        const int pid = x->simulator_pid.load();
        if (x->magic == al::kExtensionMagic && pid != 0 && al::processAlive(pid, x->simulator_start.load()))
          live.push_back({n.memory, pid});
        munmap(p, sizeof(al::SimExtension));
      }
    }
    close(fd);
  }
  return live;
}

std::vector<std::string> removeStaleObjects(const std::vector<std::string>& keep, const std::vector<std::string>& only) {
  std::vector<std::string> removed;
  for (const std::string& suffix : extensionSuffixes()) {
    const al::RobotNames n = al::namesWithSuffix(suffix);
    if (std::find(keep.begin(), keep.end(), n.memory) != keep.end()) continue;
    if (!only.empty() && std::find(only.begin(), only.end(), n.memory) == only.end()) continue;
    int pid = 0;
    const int fd = lockIfOwnerGone(n.extension, &pid);
    if (fd < 0) continue;
    shm_unlink(n.memory.c_str());
    sem_unlink(n.semaphore.c_str());
    shm_unlink(n.images.c_str());
    shm_unlink(n.extension.c_str());  // last, still locked: a simulator waiting for the lock sees it unlinked
    close(fd);
    std::fprintf(stderr, "removed stale %s and its objects (simulator pid %d is gone)\n", n.memory.c_str(), pid);
    removed.push_back(n.memory);
  }
  return removed;
}

}  // namespace simswift::bridge
