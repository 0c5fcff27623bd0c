// The only bridge between the team's code and simswift, declared in team
// types: team translation units include this, never a simswift header.
#pragma once

#include <functional>
#include <string>

#include "team/types.hpp"

namespace glue {

struct Outcome {
  bool fallen = false;
  double x = 0, y = 0;  // m, field frame (ground truth)
  SensorValues last{};  // the sensors of the last tick, in the team's type
};

// Runs a scenario (YAML text) for `seconds`, robot 0 driven by `motion`
// once per 10 ms tick. Throws what simswift throws (std::runtime_error).
Outcome run(const std::string& scenario_yaml, double seconds,
            std::function<void(const SensorValues&, JointValues&)> motion);

}  // namespace glue
