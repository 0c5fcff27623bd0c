#include "sim/bridge/AttachedProcesses.hpp"

#include <dirent.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <fstream>
#include <string>

namespace simswift::bridge {

namespace {

// /proc/<pid>/stat's parent pid (its fourth field, after the name in
// parentheses, which may hold spaces), or 0.
int parentOf(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  std::getline(in, stat);
  const size_t close = stat.rfind(')');
  if (close == std::string::npos) return 0;
  char state = 0;
  int ppid = 0;
  return std::sscanf(stat.c_str() + close + 1, " %c %d", &state, &ppid) == 2 ? ppid : 0;
}

std::string exeOf(int pid) {
  char buf[4096];
  const std::string link = "/proc/" + std::to_string(pid) + "/exe";
  const ssize_t n = readlink(link.c_str(), buf, sizeof buf);
  return n > 0 ? std::string(buf, static_cast<size_t>(n)) : std::string();
}

}  // namespace

bool launchedBySelf(int pid) {
  const int self = getpid();
  const std::string own_exe = exeOf(self);
  // Up the parents (a bounded walk: pids are reused, a chain is not long).
  for (int p = pid, steps = 0; p > 1 && steps < 64; p = parentOf(p), ++steps)
    if (parentOf(p) == self && !own_exe.empty() && exeOf(p) == own_exe) return true;
  return false;
}

std::vector<AttachedProcess> processesMapping(const std::string& shm_name) {
  std::vector<AttachedProcess> found;
  const std::string path = "/dev/shm" + shm_name;
  DIR* d = opendir("/proc");
  if (!d) return found;
  while (dirent* e = readdir(d)) {
    if (!std::isdigit(static_cast<unsigned char>(e->d_name[0]))) continue;
    const int pid = std::atoi(e->d_name);
    if (pid == getpid() || launchedBySelf(pid)) continue;
    std::ifstream maps(std::string("/proc/") + e->d_name + "/maps");
    std::string line;
    bool maps_it = false;
    while (!maps_it && std::getline(maps, line)) {
      const size_t at = line.find(path);
      // The path ends the line or is followed by " (deleted)".
      maps_it = at != std::string::npos && (at + path.size() == line.size() || line[at + path.size()] == ' ');
    }
    if (!maps_it) continue;
    std::ifstream comm(std::string("/proc/") + e->d_name + "/comm");
    AttachedProcess p;
    p.pid = pid;
    std::getline(comm, p.name);
    found.push_back(p);
  }
  closedir(d);
  return found;
}

}  // namespace simswift::bridge
