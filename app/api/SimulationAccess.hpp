// The library's own view of a Simulation's runner (not installed): the walk
// test kit reads ground truth (feet, falls) that the public API does not give.
#pragma once

#include "simswift/Simulation.hpp"

namespace simswift::runner {
class Runner;
}

namespace simswift::api {

struct SimulationAccess {
  static const runner::Runner& runner(const Simulation& s);
  static bool started(const Simulation& s);  // the world exists (after the first step)
};

}  // namespace simswift::api
