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

// Processes that map /dev/shm<shm_name> ("/libagent-memory210"), other
// than this one and those it launched itself (launchedBySelf), which
// simswift stops at the end of the run, so nobody needs to.
std::vector<AttachedProcess> processesMapping(const std::string& shm_name);

// Whether `pid` is, or descends from, a child of this process that runs this
// process's own executable (forked, never exec'd): the init of a launched
// program (sim/programs/ProgramProcess.cpp, PID 1 of the program's PID
// namespace, which keeps simswift's mappings of every robot's block), its
// program and everything that program started.
bool launchedBySelf(int pid);

}  // namespace simswift::bridge
