// Is the simulator (or program) at the other end of a shared object still
// there? Read from /proc: wall-clock liveness only, never simulation.
#include <signal.h>

#include <cerrno>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <string>

#include "common/libagent/SimExtension.hpp"

namespace common::libagent {

namespace {
// State letter and start time (field 22) of /proc/<pid>/stat; false if absent.
bool readStat(int pid, char* state, uint64_t* start) {
  char path[64];
  std::snprintf(path, sizeof path, "/proc/%d/stat", pid);
  FILE* f = std::fopen(path, "r");
  if (!f) return false;
  char buf[1024];
  const size_t n = std::fread(buf, 1, sizeof buf - 1, f);
  std::fclose(f);
  buf[n] = '\0';
  // The command name (field 2) may hold spaces: fields resume after the last ')'.
  const char* p = std::strrchr(buf, ')');
  if (!p || p[1] == '\0') return false;
  p += 2;
  *state = *p;
  // Fields 3 (state) .. 22 (starttime): skip 19 separators.
  for (int field = 3; field < 22 && p; ++field) {
    p = std::strchr(p, ' ');
    if (p) ++p;
  }
  if (!p) return false;
  *start = std::strtoull(p, nullptr, 10);
  return true;
}
}  // namespace

uint64_t processStartTime(int pid) {
  char state = 0;
  uint64_t start = 0;
  return readStat(pid, &state, &start) ? start : 0;
}

bool processAlive(int pid, uint64_t start) {
  if (pid <= 0) return false;
  // A program simswift launched in a PID namespace of its own
  // (sim/programs/ProgramView.hpp) cannot see its simulator's pid; it ends
  // with its simulator, so the simulator is alive while it runs.
  if (const char* v = std::getenv("SIMSWIFT_PID_NAMESPACE_OF_PROGRAM"); v && v[0] == '1') return true;
  if (kill(pid, 0) != 0 && errno != EPERM) return false;
  char state = 0;
  uint64_t s = 0;
  if (!readStat(pid, &state, &s)) return errno == EPERM;  // no /proc: trust kill()
  if (state == 'Z' || state == 'X') return false;
  return start == 0 || s == start;
}

}  // namespace common::libagent
