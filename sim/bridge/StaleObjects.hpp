// Named objects of other simulators in /dev/shm: those a killed run left
// (removed) and those a running one owns (named).
#pragma once

#include <string>
#include <vector>

namespace simswift::bridge {

// Unlinks the named objects (extension, block, semaphore, images) of every
// simulated robot in /dev/shm whose owning simulator is gone (killed
// without cleaning up), except robots whose memory name is in `keep` (this
// run takes those over, adopting what a waiting program opened). Returns
// the memory names removed. Objects without a simswift extension (a robot
// program waiting for its simulator) are left alone.
// With `only` non-empty, just those memory names are looked at.
std::vector<std::string> removeStaleObjects(const std::vector<std::string>& keep,
                                            const std::vector<std::string>& only = {});

// Robots in /dev/shm whose simulator still runs (memory name, its pid).
struct LiveRobot {
  std::string memory;
  int pid = 0;
};
std::vector<LiveRobot> liveRobots();

}  // namespace simswift::bridge
