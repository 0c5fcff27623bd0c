// What watches a run from outside without changing it: the Runner calls
// each observer at the end of every tick (stage 13, Runner.hpp), while no
// robot thread runs, with the finished tick's state readable through the
// const Runner. An observer reads; it never writes the world or talks to a
// program (the recorder, sim/record, is one).
#pragma once

#include <cstdint>

namespace simswift::runner {

class Runner;

class TickObserver {
 public:
  virtual ~TickObserver() = default;
  // The tick that ended at t_us (us of simulated time since the start).
  virtual void observe(const Runner& runner, int64_t t_us) = 0;
};

}  // namespace simswift::runner
