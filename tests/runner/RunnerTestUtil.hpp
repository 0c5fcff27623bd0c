// Helpers the runner tests share: the build folder, a run's options without
// the progress line, a one-robot scenario's robots.
#pragma once

#include <string>

#include "sim/runner/Runner.hpp"

namespace runnertest {

// The build folder: simswift, simswift-agent and the libagent clients.
inline const std::string kBin = SIMSWIFT_BINARY_DIR;

inline simswift::runner::RunOptions quiet() {
  simswift::runner::RunOptions o;
  o.progress = false;
  return o;
}

// The robots of a one-robot scenario (team 0, player 1, at x = -1 m).
inline const std::string kOneRobot = "robots:\n  - {team: 0, player: 1, x: -1, y: 0}\n";

}  // namespace runnertest
