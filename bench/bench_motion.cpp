// Motion benchmark: achieved / commanded speed of the walk at
// 25, 50, 75 and 100 % of each limit (walk gains at 1.0: no calibration;
// mean of seeds 1-3, spread printed), heading drift of a combined forward +
// sideways walk, the joints' hinge-anchor separation and the stance feet's
// slip over a 20 s walk at full speed, falls per 100 random 20 s command
// sequences, and the real-time factor of one walking robot with its Motion
// thread in the loop. The walk runs through the robot program's production
// schedule (inline): the bench plays Behaviour through a RequestedBehaviour
// (agent/behaviour/RequestedBehaviour.hpp) in the Perception thread's
// behaviour slot, and the standard Motion module follows its requests.
// Figures go to stdout and the results file. Every walk figure (achieved /
// commanded, heading drift, stance slip, falls) is measured by the walk test
// kit's WalkMeter (include/simswift/WalkTest.hpp), the one home of those
// measurements: a team's walk test prints the same figures.
//
//   bench_motion [--sequences N] [--only SECTIONS]
//     --sequences: random 20 s sequences for falls and the RTF (default 100)
//     --only: comma-separated subset of ratios,combined,joints,falls (default all)
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>
#include <algorithm>

#include "BenchResults.hpp"
#include "agent/blackboard/Blackboard.hpp"
#include "agent/behaviour/RequestedBehaviour.hpp"
#include "app/api/WalkSampling.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"
#include "simswift/WalkTest.hpp"

namespace {

using agent::blackboard::ActionType;

struct Rig {
  std::shared_ptr<agent::behaviour::MotionRequestMailbox> behaviour;  // the bench's motion requests
  simswift::runner::Runner runner;
  explicit Rig(uint64_t seed, double x = 0.0)  // x: start on the field (m)
      : runner(simswift::runner::Scenario::parse(
            "seed: " + std::to_string(seed) + "\nnoise: on\nrobots:\n  - {team: 0, player: 1, x: " + std::to_string(x) + ", y: 0}\n",
            "bench_motion")) {
    auto b = std::make_unique<agent::behaviour::RequestedBehaviour>();
    behaviour = b->mailbox();
    runner.programs().setBehaviour(0, std::move(b));
    runner.programs().setThreading(agent::program::Threading::Inline);  // as the experiment runs programs
    runner.start();
  }
  void walk(double f, double l, double t) {
    behaviour->set([&](agent::blackboard::MotionRequest& r) {
      r.body.type = ActionType::WALK;
      r.body.forward = static_cast<float>(f);
      r.body.left = static_cast<float>(l);
      r.body.turn = static_cast<float>(t);
      ++r.sequence;
    });
  }
  // Ticks `s` seconds, each tick's ground truth to `meter` if given.
  void run(double s, simswift::WalkMeter* meter = nullptr) {
    for (int i = 0; i < static_cast<int>(std::lround(s / 0.01)); ++i) {
      runner.tick();
      if (meter) meter->add(sample());
    }
  }
  simswift::WalkSample sample() const { return simswift::api::walkSample(runner, 0); }
  // Commands a walk, lets it start for `settle` s, measures `window` s.
  simswift::WalkFigures measure(double f, double l, double t, double settle, double window) {
    walk(f, l, t);
    run(settle);
    simswift::WalkMeter meter;
    meter.begin(sample(), {f, l, t});
    run(window, &meter);
    return meter.figures();
  }
};

double uniform(uint64_t& x) {  // [-1, 1)
  x = x * 6364136223846793005ULL + 1442695040888963407ULL;
  return 2.0 * static_cast<double>(x >> 11) / 9007199254740992.0 - 1.0;
}

}  // namespace

int main(int argc, char** argv) {
  int sequences = 100;
  std::string only = "ratios,combined,joints,falls";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sequences") && i + 1 < argc) {
      sequences = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--only") && i + 1 < argc) {
      only = argv[++i];
    } else {
      std::fprintf(stderr, "bench_motion: unknown argument '%s' (--sequences N, --only ratios,combined,joints,falls)\n",
                   argv[i]);
      return 2;
    }
  }
  auto wanted = [&](const char* section) { return ("," + only + ",").find(std::string(",") + section + ",") != std::string::npos; };
  namespace sb = simswift::bench;

  // Achieved / commanded, 6 s measured after a 2 s start (WalkTest::walk's
  // defaults); seeds 1-3.
  const char* names[3] = {"forward", "left", "turn"};
  const double limits[3] = {300, 200, 0.8};
  for (int axis = 0; axis < 3 && wanted("ratios"); ++axis) {
    for (int pct : {25, 50, 75, 100}) {
      double sum = 0, lo = 1e9, hi = -1e9;
      for (uint64_t seed = 1; seed <= 3; ++seed) {
        Rig rig(seed);
        const double cmd = limits[axis] * pct / 100.0;
        const simswift::WalkFigures f =
            rig.measure(axis == 0 ? cmd : 0, axis == 1 ? cmd : 0, axis == 2 ? cmd : 0, 2.0, 6.0);
        const double ratio = axis == 0 ? f.forward_ratio : axis == 1 ? f.left_ratio : f.turn_ratio;
        sum += ratio;
        lo = std::min(lo, ratio);
        hi = std::max(hi, ratio);
        if (pct == 100) std::printf("  (seed %d: %s)\n", static_cast<int>(seed), f.summary().c_str());
      }
      std::printf("  (%s %d %%: seeds 1-3 range %.2f-%.2f)\n", names[axis], pct, lo, hi);
      sb::report(std::string("motion.walk.") + names[axis] + "." + std::to_string(pct) + "pct.achieved_ratio",
                 sum / 3, "ratio");
    }
  }

  // Combined forward 200 + left 100 mm/s for 10 s: achieved per axis and
  // heading drift (no turn asked).
  if (wanted("combined")) {
    Rig rig(4);
    // The heading's least-squares slope beside end-to-start (the walk's
    // per-step yaw wobble, +-0.02-0.03 rad, weighs on the latter).
    const simswift::WalkFigures f = rig.measure(200, 100, 0, 2.0, 10.0);
    std::printf("  (%s)\n", f.summary().c_str());
    sb::report("motion.walk.combined_200_100.forward_ratio", f.forward_ratio, "ratio");
    sb::report("motion.walk.combined_200_100.left_ratio", f.left_ratio, "ratio");
    sb::report("motion.walk.combined_200_100.heading_drift", std::fabs(f.turn) * 1000, "mrad/s");
    sb::report("motion.walk.combined_200_100.heading_drift_slope", std::fabs(f.heading_slope) * 1000, "mrad/s");
  }

  // Joints and feet over a 20 s walk at 300 mm/s (after a 2 s start).
  if (wanted("joints")) {
    Rig rig(5, -3.5);
    rig.walk(300, 0, 0);
    rig.run(2.0);
    simswift::WalkMeter meter;
    meter.begin(rig.sample(), {300, 0, 0});
    double anchors = 0;
    std::vector<double> per_tick;
    const std::clock_t c0 = std::clock();
    for (int i = 0; i < 2000; ++i) {
      rig.runner.tick();
      const double a = rig.runner.world().robot(0).anchorSeparation();
      anchors = std::max(anchors, a);
      per_tick.push_back(a);
      meter.add(rig.sample());
    }
    const simswift::WalkFigures f = meter.figures();
    const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    std::printf("  (20 s walk: %s)\n", f.summary().c_str());
    std::sort(per_tick.begin(), per_tick.end());
    std::printf("  (anchor separation per tick: median %.2f, 90 %% %.2f, 99 %% %.2f mm)\n",
                per_tick[per_tick.size() / 2] * 1000, per_tick[per_tick.size() * 9 / 10] * 1000,
                per_tick[per_tick.size() * 99 / 100] * 1000);
    sb::report("motion.walk.hinge_anchor_separation.max", anchors * 1000, "mm");
    sb::report("motion.walk.stance_slip.mean", f.slip_mean, "mm/step");
    sb::report("motion.walk.stance_slip.max", f.slip_max, "mm/step");
    // CPU-time real-time factor of this one walk (a quick figure for solver
    // comparisons; the random sequences below give the steadier one).
    sb::report("motion.walk.straight_20s.real_time_factor_cpu", 20.0 / cpu, "x");
  }

  // Falls per 100 random 20 s sequences (a new command every 2 s): a
  // sequence with any fall (WalkSample::falls: the simulator's detector,
  // torso origin below FallDetector::kFallHeight, the meter's count) counts one.
  if (!wanted("falls")) return 0;
  int falls = 0;
  double sim_s = 0, wall_s = 0, cpu_s = 0;
  for (int s = 0; s < sequences; ++s) {
    Rig rig(1000 + s);
    uint64_t x = 77 + static_cast<uint64_t>(s);
    const auto w0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    for (int k = 0; k < 10; ++k) {
      rig.walk(300 * uniform(x), 200 * uniform(x), 0.8 * uniform(x));
      rig.run(2.0);
    }
    wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    cpu_s += static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    sim_s += 20.0;
    if (rig.sample().falls > 0) ++falls;
  }
  sb::report("motion.random_sequences.falls_per_100", 100.0 * falls / sequences, "falls");
  sb::report("motion.walking_robot.real_time_factor", sim_s / wall_s, "x");
  // CPU time of the whole process (physics, sensors and the Motion thread):
  // steadier than the wall clock on a shared machine.
  sb::report("motion.walking_robot.real_time_factor_cpu", sim_s / cpu_s, "x");
  return 0;
}
