// Throwaway tuning harness for the kick (DISABLED_: run by hand). Kicks a
// ball placed as MotionPhysics.FullPowerKick* places it, on KICK_N seeds from
// KICK_SEED_BASE (default 900: tune on other seeds than the tests' 200-239),
// with the KickConfig fields overridden by KICK_<FIELD> (e.g. KICK_WIND_BACK=90,
// KICK_REACH, KICK_LIFT, KICK_SHIFT, KICK_HEIGHT, KICK_STRIKE_TIME_FAST).
// KICK_FOOT=left|right (default right). Prints one line per kick and a summary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/runner/motion_harness.hpp"

using agent::blackboard::ActionType;
using agent::blackboard::Foot;
using motion_test::MotionHarness;

namespace {
void override(const char* name, double* field) {
  if (const char* e = std::getenv(name)) *field = std::atof(e);
}
}  // namespace

TEST(MotionKickTuning, DISABLED_Distances) {
  agent::motion::MotionConfig cfg;
  override("KICK_SHIFT", &cfg.kick.shift);
  override("KICK_HEIGHT", &cfg.kick.height);
  override("KICK_LIFT", &cfg.kick.lift);
  override("KICK_WIND_BACK", &cfg.kick.wind_back);
  override("KICK_REACH", &cfg.kick.reach);
  override("KICK_STRIKE_TIME_FAST", &cfg.kick.strike_time_fast);
  const char* foot_env = std::getenv("KICK_FOOT");
  const Foot foot = foot_env && std::string(foot_env) == "left" ? Foot::LEFT : Foot::RIGHT;
  const int n = std::getenv("KICK_N") ? std::atoi(std::getenv("KICK_N")) : 10;
  const int base = std::getenv("KICK_SEED_BASE") ? std::atoi(std::getenv("KICK_SEED_BASE")) : 900;
  std::vector<double> d;
  int fell = 0;
  for (int s = base; s < base + n; ++s) {
    const double y = foot == Foot::RIGHT ? -0.05 : 0.05;
    MotionHarness h(static_cast<uint64_t>(s), -3.0, 0.0, 0.0,
                    "ball: {x: " + std::to_string(-3.0 + 0.17) + ", y: " + std::to_string(y) + "}\n", cfg);
    h.request(ActionType::STAND);
    h.run(1.0);
    const Eigen::Vector3d b0 = h.runner().world().ballPosition();
    h.kick(foot, 1.0, 0.0);
    if (!h.run(6.0)) ++fell;
    d.push_back((h.runner().world().ballPosition() - b0).head<2>().norm());
  }
  std::sort(d.begin(), d.end());
  const auto far = std::count_if(d.begin(), d.end(), [](double x) { return x >= 2.5; });
  std::printf("KICK %s n %d: >=2.5 m %ld, min %.2f median %.2f max %.2f, falls %d\n",
              foot == Foot::RIGHT ? "right" : "left", n, static_cast<long>(far), d.front(), d[d.size() / 2],
              d.back(), fell);
}
