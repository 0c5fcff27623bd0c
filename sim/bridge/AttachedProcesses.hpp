// Which other processes have a named shared-memory object mapped (read from
// /proc/<pid>/maps): at the end of a run, the robot programs still attached
// to a robot's libagent block, named so the user can stop them.
#pragma once

#include <string>
#include <vector>

namespace simswift::bridge {

struct AttachedProcess {
  int pid = 0;
  std::string name;  // /proc/<pid>/comm
};

// Processes other than this one that map /dev/shm<shm_name> ("/libagent-memory210").
std::vector<AttachedProcess> processesMapping(const std::string& shm_name);

}  // namespace simswift::bridge
