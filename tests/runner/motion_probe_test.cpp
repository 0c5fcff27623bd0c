// TEMPORARY tuning probe (disabled unless MOTION_PROBE is set).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "tests/runner/motion_harness.hpp"

using agent::blackboard::ActionType;
using motion_test::MotionHarness;

namespace {
void apply(agent::motion::MotionConfig& c, const std::string& k, double v) {
  auto& w = c.walk;
  if (k == "x") w.foot_x_offset = v;
  else if (k == "lean") w.torso_lean = v;
  else if (k == "sway") w.sway = v;
  else if (k == "h") w.walk_hip_height = v;
  else if (k == "lift") w.base_lift = v;
  else if (k == "gp") w.gyro_pitch_gain = v;
  else if (k == "gr") w.gyro_roll_gain = v;
  else if (k == "width") w.stance_width_extra = v;
  else if (k == "T") w.period = v;
  else if (k == "min") w.switch_min_fraction = v;
  else if (k == "arm") w.arm_swing = v;
  else if (k == "fg") w.forward_gain = v;
  else if (k == "lg") w.left_gain = v;
  else if (k == "tg") w.turn_gain = v;
  else if (k == "tw") w.turn_width = v;
  else ADD_FAILURE() << "unknown " << k;
}
}  // namespace

TEST(MotionProbe, Walk) {
  const char* env = std::getenv("MOTION_PROBE");
  if (!env) GTEST_SKIP();
  agent::motion::MotionConfig cfg;
  double f = 300, l = 0, t = 0;
  uint64_t seed = 1;
  std::stringstream ss(env);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto eq = item.find('=');
    const std::string k = item.substr(0, eq);
    const double v = std::atof(item.c_str() + eq + 1);
    if (k == "f") f = v; else if (k == "l") l = v; else if (k == "t") t = v; else if (k == "seed") seed = v;
    else apply(cfg, k, v);
  }
  MotionHarness h(seed, -3, 0, 0, "", cfg);
  h.request(ActionType::STAND);
  h.run(1.0);
  h.request(ActionType::WALK, f, l, t);
  bool ok = h.run(2.0);
  const auto p0 = h.pose();
  const auto s0 = h.motion().walk().stepsTaken();
  const auto o0 = h.state().odometry;
  // Loading: fraction of mid-swing ticks where the swing foot carries < 20 %.
  int mid = 0, unloaded = 0;
  for (int i = 0; i < 600; ++i) {
    ok = h.run(0.01) && ok;
    const auto& w = h.motion().walk();
    const double fr = w.stepTime() / w.stepPeriod();
    if (fr > 0.3 && fr < 0.7) {
      ++mid;
      const double fl = h.runner().sensors(0).trueFootForce(true), frr = h.runner().sensors(0).trueFootForce(false);
      const double swing = w.leftIsSwing() ? fl : frr;
      if (swing < 0.2 * (fl + frr)) ++unloaded;
    }
  }
  std::printf("mid-swing unloaded fraction %.2f\n", mid ? double(unloaded) / mid : 0.0);
  const auto p1 = h.pose();
  const auto o1 = h.state().odometry;
  const double c = std::cos(p0.theta), s = std::sin(p0.theta);
  const double dx = p1.x - p0.x, dy = p1.y - p0.y;
  const double fwd = c * dx + s * dy, side = -s * dx + c * dy;
  std::printf("PROBE %s: ok %d fwd %.0f mm/s side %.0f mm/s turn %.3f rad/s steps/s %.2f odo f %.0f l %.0f t %.3f z %.3f\n", env, ok,
              fwd / 6 * 1000, side / 6 * 1000, motion_test::wrapAngle(p1.theta - p0.theta) / 6,
              (h.motion().walk().stepsTaken() - s0) / 6.0, (o1.forward - o0.forward) / 6, (o1.left - o0.left) / 6,
              (o1.turn - o0.turn) / 6, h.torsoHeight());
}
