// Vision oracle cost:
//  - microseconds of oracle work per 30 Hz camera frame for 3 robots (both
//    cameras each), default detector model, in a game-like scene (robots
//    facing each other across the centre circle, ball between them);
//  - the same with robots walking (3 robots, Motion in the loop, scenario
//    actions): the oracle's time per frame and its share of the run's wall
//    time, and the run's real-time factor.
// Usage: bench_vision [--frames N] [--seconds S] [--out FILE]
// Wall-clock time is measured here only; the simulation never reads it.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "BenchResults.hpp"
#include "BenchSetup.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"
#include "sim/vision/VisionOracle.hpp"

using namespace simswift;
using bench::Clock;
using bench::seconds;

namespace {

// 3 robots walking through the runner (which runs the oracle in every
// frame). At each frame the bench also times one extra oracle pass over the
// runner's world: comparing two whole runs would drown the oracle's share in
// the noise of a shared machine.
struct Walking {
  double rtf = 0;          // whole run, oracle included once (the runner's)
  double us_per_frame = 0; // oracle, 3 robots x 2 cameras
  double share = 0;        // oracle time / run time without the extra pass
  double observations = 0; // per robot per frame
  int falls = 0;
};
Walking walking(double sim_s) {
  const std::string walk = "actions: [{t: 0.5, action: walk, forward: 200, turn: 0.2}]";
  runner::Scenario sc = runner::Scenario::parse(
      std::string("seed: 1\nnoise: on\nball: {x: 0.0, y: 0.0}\nrobots:\n") +
          "  - {team: 0, player: 1, x: -1.5, y: 0.0, theta: 0.0, " + walk + "}\n" +
          "  - {team: 0, player: 2, x: -1.0, y: 1.5, theta: -0.8, " + walk + "}\n" +
          "  - {team: 1, player: 1, x: 1.5, y: -0.5, theta: 3.14159, " + walk + "}\n",
      "bench_vision");
  runner::Runner r(sc);
  r.programs().setThreading(agent::program::Threading::Inline);
  r.start();
  vision::VisionOracle extra(r.world().field(), sc.vision, sc.seed);
  extra.setTeams({0, 0, 1}, {0, 0, 1});
  common::libagent::CameraFrame f{};
  const int64_t ticks = common::nao::ticksIn(sim_s);
  int64_t last = -1, frames = 0;
  double oracle_s = 0;
  int64_t obs = 0;
  const auto t0 = Clock::now();
  for (int64_t k = 0; k < ticks; ++k) {
    r.tick();
    const int64_t frame = r.ticks() * 10000 * 30 / 1000000;
    if (frame == last) continue;
    last = frame;
    const auto a = Clock::now();
    f.frame_index = frame;
    int n = 0;
    for (int i = 0; i < 3; ++i) {
      extra.fill(r.world(), i, f);
      n += f.num_observations;
    }
    oracle_s += seconds(a, Clock::now());
    obs += n;
    ++frames;
  }
  const double wall = seconds(t0, Clock::now()) - oracle_s;
  const int falls = r.stats().falls;
  r.shutdown();
  Walking w;
  w.rtf = sim_s / wall;
  w.us_per_frame = frames ? oracle_s * 1e6 / frames : 0;
  w.share = 100.0 * oracle_s / wall;
  w.observations = frames ? obs / (3.0 * frames) : 0;
  w.falls = falls;
  return w;
}

}  // namespace

int main(int argc, char** argv) {
  bench::FrameArgs args;
  args.frames = 3000;
  if (!bench::parseFrameArgs(argc, argv, &args)) return 2;
  const std::string& out = args.out;
  const int frames = args.frames;
  const double sim_seconds = args.sim_seconds;

  // --- The oracle alone, 3 robots, static game-like scene.
  {
    const auto model = bench::loadNao();
    const auto q = bench::standingPosture(*model);
    World world(FieldConfig::spl2017());
    world.addRobot(model, -1.5, 0.0, 0.0, q);
    world.addRobot(model, -1.0, 1.5, -0.8, q);
    world.addRobot(model, 1.5, -0.5, M_PI, q);
    world.placeBall(0.2, 0.1);
    vision::VisionOracle oracle(world.field(), vision::VisionConfig{}, 1);
    oracle.setTeams({0, 0, 1}, {0, 0, 1});
    common::libagent::CameraFrame f{};
    int64_t observations = 0;
    const auto t0 = Clock::now();
    for (int k = 0; k < frames; ++k) {
      f.frame_index = k;
      for (int r = 0; r < 3; ++r) {
        oracle.fill(world, r, f);
        observations += f.num_observations;
      }
    }
    const double us = seconds(t0, Clock::now()) * 1e6 / frames;
    bench::report("vision oracle: us per frame, 3 robots x 2 cameras", us, "us", out.c_str());
    bench::report("vision oracle: observations per robot per frame", observations / (3.0 * frames), "obs", out.c_str());
    bench::report("vision oracle: share of a 33.3 ms frame, 3 robots", 100.0 * us / (1e6 / 30), "%", out.c_str());
  }

  // --- 3 walking robots through the runner.
  const Walking w = walking(sim_seconds);
  bench::report("3 robots walking (oracle on): real-time factor", w.rtf, "x", out.c_str());
  bench::report("3 robots walking: oracle us per frame, 3 robots", w.us_per_frame, "us", out.c_str());
  bench::report("3 robots walking: oracle share of run time", w.share, "%", out.c_str());
  bench::report("3 robots walking: observations per robot per frame", w.observations, "obs", out.c_str());
  if (w.falls) std::printf("(note: %d falls during the walk: blind frames lower the oracle's cost)\n", w.falls);
  return 0;
}
