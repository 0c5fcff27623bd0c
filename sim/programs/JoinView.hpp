// A robot's view that a run holds for programs started by hand (an external
// robot's: Programs::makeExternal), joined by `simswift attach`: the command
// runs in the robot's PID and network namespaces (the run's init of it,
// named in the robot's clock page) and in a mount namespace of its own made
// as a launched program's (ProgramView.hpp) on the run's folder of the view,
// so it sees what a launched program sees: /tmp (the robot's, shared with
// every other command joined to it), /tmp/robocup, /home/nao, the robot's
// files, wlan0, its own /proc; and, as for a launched program, the
// machine's folders under /tmp its command names. It ends with the run, as a
// launched program does (docs/porting.md section 10).
//
// The order is the kernel's: the user namespace first (when the run made one:
// simswift not root), then network and PID (setns, in the still
// single-threaded attach); the PID namespace takes the children forked after
// it, so the mounts are made in the forked child (enterJoinedMounts), which
// then execs the command.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/programs/ProgramView.hpp"

namespace simswift::programs {

// What a robot's clock page (common/clock/ClockPage.hpp) says of its run, read
// once its run has set it up (its magic, written last) and while that run
// lives (its pid; a killed run's page is not read).
struct RunPage {
  uint32_t flags = 0;     // common::clock::kFlag*
  int64_t tick_ns = 0;
  int view_pid = 0;       // with kFlagView
  std::string view_folder;
};
// Nothing while the page is not there, not set up, of another version, not
// this user's, its run is gone, or its view is not named by a pid and an
// absolute folder.
std::optional<RunPage> readRunPage(const std::string& name);

// Enters the view's user namespace (when another than the caller's), network
// and PID namespaces (/proc/<view_pid>/ns/). The caller must be single
// threaded. "" on success, else why not (naming the step).
std::string enterViewNamespaces(int view_pid);

// The mounts of a command joining the view at `folder` (the run's, as its
// page says), the robot's LoLA socket bound at /tmp/robocup ("" for none: a
// V5), the machine's folders under /tmp that `named` (the command, its
// folder, its environment values) names. Throws std::runtime_error.
std::vector<MountOp> joinedMounts(const std::string& folder, const std::string& robocup_socket,
                                  const std::vector<std::string>& named);

// In the forked child (already in the view's PID namespace): a mount
// namespace of its own, every mount private, then `mounts`. Syscalls only.
// 0, or the errno of the step that failed (*what names it).
int enterJoinedMounts(const std::vector<MountOp>& mounts, const char** what);

}  // namespace simswift::programs
