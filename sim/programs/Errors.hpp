// The errors a run ends with. The program side (the drivers, their factory)
// throws them and so does the Runner, which builds on it; they are here so
// that sim/programs needs nothing of sim/runner. The Runner's callers catch
// them by the runner's names (sim/runner/Errors.hpp).
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace simswift::programs {

struct WatchdogError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct RunnerError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// A launched robot program ended, crashed or could not be started: the
// message names the robot, how it ended and its log's last lines.
struct ProgramError : RunnerError {
  ProgramError(const std::string& message, std::string brief_)
      : RunnerError(message), brief(std::move(brief_)) {}
  // The same in one line without pids or paths ("t19p2: program killed by
  // signal 11 (Segmentation fault)"): what a results file may keep.
  std::string brief;
};

}  // namespace simswift::programs
