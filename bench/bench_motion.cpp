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
// Figures go to stdout and the results file.
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
#include "sim/runner/HeadingDrift.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"
#include "sim/runner/StanceSlip.hpp"

namespace {

using agent::blackboard::ActionType;

struct Rig {
  std::shared_ptr<agent::behaviour::MotionRequestMailbox> behaviour;  // the bench's motion requests
  simswift::runner::Runner runner;
  int torso;
  explicit Rig(uint64_t seed, double x = 0.0)  // x: start on the field (m)
      : runner(simswift::runner::Scenario::parse(
            "seed: " + std::to_string(seed) + "\nnoise: on\nrobots:\n  - {team: 0, player: 1, x: " + std::to_string(x) + ", y: 0}\n",
            "bench_motion")) {
    auto b = std::make_unique<agent::behaviour::RequestedBehaviour>();
    behaviour = b->mailbox();
    runner.programs().setBehaviour(0, std::move(b));
    runner.programs().setThreading(agent::program::Threading::Inline);  // as the experiment runs programs
    runner.start();
    torso = runner.world().robot(0).model().rootLink();
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
  // Ticks `s` seconds; returns false if the torso went below 0.2 m.
  bool run(double s, double* yaw_turned = nullptr) {
    bool up = true;
    double last = yaw();
    for (int i = 0; i < static_cast<int>(std::lround(s / 0.01)); ++i) {
      runner.tick();
      if (z() < 0.2) up = false;
      if (yaw_turned) {
        const double y = yaw();
        *yaw_turned += std::atan2(std::sin(y - last), std::cos(y - last));
        last = y;
      }
    }
    return up;
  }
  Eigen::Isometry3d pose() { return runner.world().robot(0).linkPose(torso); }
  double z() { return pose().translation().z(); }
  double yaw() {
    const Eigen::Vector3d x = pose().rotation().col(0);
    return std::atan2(x.y(), x.x());
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

  // Achieved / commanded, 6 s measured after a 2 s start; seeds 1-3.
  const char* names[3] = {"forward", "left", "turn"};
  const double limits[3] = {300, 200, 0.8};
  for (int axis = 0; axis < 3 && wanted("ratios"); ++axis) {
    for (int pct : {25, 50, 75, 100}) {
      double sum = 0, lo = 1e9, hi = -1e9;
      for (uint64_t seed = 1; seed <= 3; ++seed) {
        Rig rig(seed);
        const double cmd = limits[axis] * pct / 100.0;
        rig.walk(axis == 0 ? cmd : 0, axis == 1 ? cmd : 0, axis == 2 ? cmd : 0);
        rig.run(2.0);
        const Eigen::Isometry3d p0 = rig.pose();
        double turned = 0;
        rig.run(6.0, &turned);
        const Eigen::Vector3d d = p0.rotation().transpose() * (rig.pose().translation() - p0.translation());
        const double achieved = axis == 0 ? d.x() * 1000 / 6 : axis == 1 ? d.y() * 1000 / 6 : turned / 6;
        sum += achieved / cmd;
        lo = std::min(lo, achieved / cmd);
        hi = std::max(hi, achieved / cmd);
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
    rig.walk(200, 100, 0);
    rig.run(2.0);
    const Eigen::Isometry3d p0 = rig.pose();
    // Heading every tick for its least-squares slope (the walk's per-step
    // yaw wobble, +-0.02-0.03 rad, weighs on the end-to-start figure).
    double turned = 0;
    simswift::runner::HeadingDrift drift;
    for (int i = 1; i <= 1000; ++i) {
      rig.run(0.01, &turned);
      drift.add(i * 0.01, turned);
    }
    const double slope = drift.slope();
    const Eigen::Vector3d d = p0.rotation().transpose() * (rig.pose().translation() - p0.translation());
    sb::report("motion.walk.combined_200_100.forward_ratio", d.x() * 1000 / 10 / 200, "ratio");
    sb::report("motion.walk.combined_200_100.left_ratio", d.y() * 1000 / 10 / 100, "ratio");
    sb::report("motion.walk.combined_200_100.heading_drift", std::fabs(turned) / 10 * 1000, "mrad/s");
    sb::report("motion.walk.combined_200_100.heading_drift_slope", std::fabs(slope) * 1000, "mrad/s");
  }

  // Joints and feet over a 20 s walk at 300 mm/s (after a 2 s start).
  if (wanted("joints")) {
    Rig rig(5, -3.5);
    rig.walk(300, 0, 0);
    rig.run(2.0);
    simswift::runner::StanceSlip slip;
    double anchors = 0;
    std::vector<double> per_tick;
    const std::clock_t c0 = std::clock();
    for (int i = 0; i < 2000; ++i) {
      rig.runner.tick();
      const double a = rig.runner.world().robot(0).anchorSeparation();
      anchors = std::max(anchors, a);
      per_tick.push_back(a);
      slip.tick(rig.runner.world());
    }
    const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    std::printf("  (20 s walk: %zu stances)\n", slip.perStep().size());
    std::sort(per_tick.begin(), per_tick.end());
    std::printf("  (anchor separation per tick: median %.2f, 90 %% %.2f, 99 %% %.2f mm)\n",
                per_tick[per_tick.size() / 2] * 1000, per_tick[per_tick.size() * 9 / 10] * 1000,
                per_tick[per_tick.size() * 99 / 100] * 1000);
    sb::report("motion.walk.hinge_anchor_separation.max", anchors * 1000, "mm");
    sb::report("motion.walk.stance_slip.mean", slip.mean() * 1000, "mm/step");
    sb::report("motion.walk.stance_slip.max", slip.max() * 1000, "mm/step");
    // CPU-time real-time factor of this one walk (a quick figure for solver
    // comparisons; the random sequences below give the steadier one).
    sb::report("motion.walk.straight_20s.real_time_factor_cpu", 20.0 / cpu, "x");
  }

  // Falls per 100 random 20 s sequences (a new command every 2 s).
  if (!wanted("falls")) return 0;
  int falls = 0;
  double sim_s = 0, wall_s = 0, cpu_s = 0;
  for (int s = 0; s < sequences; ++s) {
    Rig rig(1000 + s);
    uint64_t x = 77 + static_cast<uint64_t>(s);
    bool up = true;
    const auto w0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    for (int k = 0; k < 10; ++k) {
      rig.walk(300 * uniform(x), 200 * uniform(x), 0.8 * uniform(x));
      up = rig.run(2.0) && up;
    }
    wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    cpu_s += static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    sim_s += 20.0;
    if (!up) ++falls;
  }
  sb::report("motion.random_sequences.falls_per_100", 100.0 * falls / sequences, "falls");
  sb::report("motion.walking_robot.real_time_factor", sim_s / wall_s, "x");
  // CPU time of the whole process (physics, sensors and the Motion thread):
  // steadier than the wall clock on a shared machine.
  sb::report("motion.walking_robot.real_time_factor_cpu", sim_s / cpu_s, "x");
  return 0;
}
