// Shared by the benchmarks that build a world by hand (bench_camera,
// bench_vision): their command line (--out FILE --frames N --seconds S), the
// NAO model from the source tree, its standing posture and a wall-clock
// interval. Wall-clock time is read here only; the simulation never reads it.
#pragma once

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "agent/program/Postures.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/nao_model/RobotModel.hpp"

namespace simswift::bench {

using Clock = std::chrono::steady_clock;

inline double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

struct FrameArgs {
  std::string out = SIMSWIFT_BENCH_RESULTS;  // results file
  int frames = 300;                          // frames to time
  double sim_seconds = 10.0;                 // s of simulated time for real-time factors
};

// Parses --out/--frames/--seconds over `defaults`; prints the usage and
// returns false on anything else (the caller exits 2).
inline bool parseFrameArgs(int argc, char** argv, FrameArgs* a) {
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--out") && i + 1 < argc) a->out = argv[++i];
    else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) a->frames = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--seconds") && i + 1 < argc) a->sim_seconds = std::atof(argv[++i]);
    else {
      std::fprintf(stderr, "usage: %s [--out FILE] [--frames N] [--seconds S]\n", argv[0]);
      return false;
    }
  }
  return true;
}

inline std::shared_ptr<const RobotModel> loadNao() {
  return std::make_shared<const RobotModel>(RobotModel::loadUrdf(SIMSWIFT_SOURCE_DIR "/models/nao_v5.urdf"));
}

// The robot program's standing posture (agent/program/Postures.hpp), model joint order.
inline std::vector<double> standingPosture(const RobotModel& m) {
  return simswift::NaoBinding(m).posture(agent::program::postureAngles(agent::program::Posture::Stand));
}

}  // namespace simswift::bench
