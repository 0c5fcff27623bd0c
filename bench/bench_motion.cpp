// Motion benchmark (issue 3): achieved / commanded speed of the walk at 25,
// 50, 75 and 100 % of each limit, falls per 100 random 20 s command
// sequences, and the real-time factor of one walking robot with its Motion
// thread in the loop. Figures go to stdout and the results file.
//
//   bench_motion [--sequences N]   (default 100)
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "BenchResults.hpp"
#include "agent/blackboard/Blackboard.hpp"
#include "agent/motion/MotionModule.hpp"
#include "sim/runner/Runner.hpp"

namespace {

using agent::blackboard::ActionType;

struct Rig {
  agent::blackboard::Blackboard board;
  simswift::runner::Runner runner;
  int torso;
  explicit Rig(uint64_t seed)
      : runner(simswift::runner::Scenario::parse(
            "seed: " + std::to_string(seed) + "\nnoise: on\nrobots:\n  - {team: 0, player: 1, x: 0, y: 0}\n",
            "bench_motion")) {
    runner.setMotionGenerator(0, std::make_unique<agent::motion::MotionModule>(board));
    runner.start();
    torso = runner.world().robot(0).model().rootLink();
  }
  void walk(double f, double l, double t) {
    board.motion_request.update([&](agent::blackboard::MotionRequest& r) {
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
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--sequences") && i + 1 < argc) sequences = std::atoi(argv[++i]);
  namespace sb = simswift::bench;

  // Achieved / commanded, 6 s measured after a 2 s start.
  const char* names[3] = {"forward", "left", "turn"};
  const double limits[3] = {300, 200, 0.8};
  for (int axis = 0; axis < 3; ++axis) {
    for (int pct : {25, 50, 75, 100}) {
      Rig rig(1);
      const double cmd = limits[axis] * pct / 100.0;
      rig.walk(axis == 0 ? cmd : 0, axis == 1 ? cmd : 0, axis == 2 ? cmd : 0);
      rig.run(2.0);
      const Eigen::Isometry3d p0 = rig.pose();
      double turned = 0;
      rig.run(6.0, &turned);
      const Eigen::Vector3d d = p0.rotation().transpose() * (rig.pose().translation() - p0.translation());
      const double achieved = axis == 0 ? d.x() * 1000 / 6 : axis == 1 ? d.y() * 1000 / 6 : turned / 6;
      sb::report(std::string("motion.walk.") + names[axis] + "." + std::to_string(pct) + "pct.achieved_ratio",
                 achieved / cmd, "ratio");
    }
  }

  // Falls per 100 random 20 s sequences (a new command every 2 s).
  int falls = 0;
  double sim_s = 0, wall_s = 0;
  for (int s = 0; s < sequences; ++s) {
    Rig rig(1000 + s);
    uint64_t x = 77 + static_cast<uint64_t>(s);
    bool up = true;
    const auto w0 = std::chrono::steady_clock::now();
    for (int k = 0; k < 10; ++k) {
      rig.walk(300 * uniform(x), 200 * uniform(x), 0.8 * uniform(x));
      up = rig.run(2.0) && up;
    }
    wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    sim_s += 20.0;
    if (!up) ++falls;
  }
  sb::report("motion.random_sequences.falls_per_100", 100.0 * falls / sequences, "falls");
  sb::report("motion.walking_robot.real_time_factor", sim_s / wall_s, "x");
  return 0;
}
