// The library's cost per tick: scenarios/walk_one.yaml stepped through the
// public API (Simulation::step, libsimswift.so), as a team's test steps it.
// bench/bench_api.py sets it beside Python's step() and `simswift run`.
//   build/bench/bench_api [SCENARIO] [SECONDS]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "BenchResults.hpp"
#include "simswift/Simulation.hpp"

int main(int argc, char** argv) {
  const std::string scenario = argc > 1 ? argv[1] : std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/walk_one.yaml";
  const double seconds = argc > 2 ? std::atof(argv[2]) : 20.0;
  simswift::Simulation sim = simswift::Simulation::fromScenario(scenario);
  sim.step();  // the first tick builds the world and starts the programs: not timed
  const auto t0 = std::chrono::steady_clock::now();
  const int64_t before = sim.ticks();
  sim.run(seconds);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double ticks = static_cast<double>(sim.ticks() - before);
  simswift::bench::report("api.cpp.step_us_per_tick", 1e6 * wall / ticks, "us");
  simswift::bench::report("api.cpp.real_time_factor", seconds / wall, "x");
  std::printf("hash %016llx\n", static_cast<unsigned long long>(sim.stateHash()));
  return 0;
}
