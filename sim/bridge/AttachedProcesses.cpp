#include "sim/bridge/AttachedProcesses.hpp"

#include <dirent.h>
#include <unistd.h>

#include <cctype>
#include <fstream>
#include <string>

namespace simswift::bridge {

std::vector<AttachedProcess> processesMapping(const std::string& shm_name) {
  std::vector<AttachedProcess> found;
  const std::string path = "/dev/shm" + shm_name;
  DIR* d = opendir("/proc");
  if (!d) return found;
  while (dirent* e = readdir(d)) {
    if (!std::isdigit(static_cast<unsigned char>(e->d_name[0]))) continue;
    const int pid = std::atoi(e->d_name);
    if (pid == getpid()) continue;
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
