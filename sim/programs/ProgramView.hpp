// What a launched robot program sees of the machine: the robot's own view
// (docs/porting.md, "What a launched program gets").
//
// Where the machine gives namespaces (mountNamespaceSupport), a launched
// program runs under a small init of simswift's (ProgramProcess) in
//   - a PID namespace of its own: when simswift dies (also kill -9) the init
//     dies (PR_SET_PDEATHSIG) and the kernel ends every process in it, a
//     wrapper script's children included; /proc is the namespace's, so
//     `killall naoth` reaches only this robot's processes;
//   - a mount namespace of its own, in which
//       /tmp           is a per-robot folder of the run (<program_logs>/<tag>.view/tmp,
//                      emptied at launch): two programs' lock and pid files never meet;
//       /tmp/robocup   is the robot's LoLA socket (a LoLA robot);
//       the machine's folders under /tmp that the launch names (its command, cwd,
//                      environment values, the {config} file's folder) are still
//                      seen at their own paths;
//       /home/nao      is a per-robot writable folder (<tag>.view/home);
//       the robot's files (kDefaultFiles below and the scenario's `files:`)
//                      at their paths: a file's deepest existing folder on the
//                      machine is covered by a read-only overlay whose upper
//                      layer holds the new entries (the machine's own entries
//                      stay visible beneath).
// Everything here is built before the fork (folders, files, the list of
// mounts); the forked init only makes the syscalls (applyView).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace simswift::programs {

// One of the robot's files: `path` (absolute) holds `content` (mode
// `mode`), or the machine's file or folder `from` is mapped there (bound:
// a folder stays writable). `where` names its origin for errors ("file:line").
struct FileEntry {
  std::string path;
  std::string content;
  std::string from;  // "" = content
  unsigned mode = 0644;
  std::string where;
};

// Whether `path` may be one of the robot's files: "" if so, else why not.
// (Absolute, normalised, not /, not under /proc or /dev, not /tmp/robocup.)
std::string fileEntryProblem(const std::string& path);

// The files every launched program gets (before the scenario's, which may
// replace them by path): B-Human's CPU temperatures, the LoLA executable's
// two paths NaoTH looks for.
std::vector<FileEntry> defaultFiles();

// The view one launched program gets (the caller fills it; ProgramProcess
// applies it). `isolate` false: none of it (the machine gives no namespace).
struct ProgramView {
  bool isolate = false;
  std::string robocup_socket;        // bound at /tmp/robocup ("" = none)
  std::string folder;                // the per-robot folder of the run (absolute)
  std::vector<std::string> carry;    // machine paths (absolute) the program must still see
  std::vector<FileEntry> files;      // the robot's files, defaults first
  // Its own network (RobotNetwork.hpp): wlan0 with this address (host byte
  // order, 10.0.<team>.<player>); 0 = the machine's network.
  uint32_t network_address = 0;
};

// The machine's folders under /tmp that `texts` (a command's arguments, a
// cwd, environment values) name: "/tmp/<first>" for every "/tmp/..." at the
// start of a text or after '=', ':' or ',', in order, once each.
std::vector<std::string> pathsUnderTmp(const std::vector<std::string>& texts);

// One mount the init makes, in order.
struct MountOp {
  std::string source, target, fstype, data;
  unsigned long flags = 0;
  bool optional = false;  // a failure is skipped (proc where the machine forbids it)
  std::string what;       // for the error: "overlay on /usr/bin"
};

// Builds the folders and files of `view` and the mounts that make it.
// Throws std::runtime_error naming the path that could not be made.
// `prepare` false: the folder is one a run prepared for the same view (a
// program joining it: JoinView.hpp): nothing in it is removed or rewritten,
// only what is missing made (its /tmp is the robot's, shared).
std::vector<MountOp> planView(const ProgramView& view, bool prepare = true);

// In the forked init, already in its own mount namespace: makes the mounts.
// 0, or the errno of the first required mount that failed (*failed = its index).
int applyView(const std::vector<MountOp>& mounts, size_t* failed);

}  // namespace simswift::programs
