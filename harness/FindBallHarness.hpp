// Shared by the physics tests (tests/behaviour_physics) and bench_findball: table 5.1's starts, table
// 5.2's ball positions, scenario text for a ball search, and the thesis's
// "found" test (5.1: a robot sees the ball and is within 300 mm of it),
// checked both from the simulator's ground truth and from the robot's own
// Blackboard.
#pragma once

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "sim/game/Sideline.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"

namespace findball_harness {

struct Start {
  int player;
  double x, y, theta;  // mm, mm, rad (facing into the field from the touch line)
};
// Table 5.1 (robots 2, 3, 4); one robot: robot 2.
inline const std::vector<Start>& table51() {
  static const std::vector<Start> s{{2, -3250, 3000, -M_PI / 2}, {3, -2000, -3000, M_PI / 2}, {4, -1750, 3000, -M_PI / 2}};
  return s;
}
// Table 5.2, positions 1..5 (mm).
inline const std::vector<std::pair<double, double>>& table52() {
  static const std::vector<std::pair<double, double>> b{{2250, 0}, {4000, -2500}, {4000, 2500}, {4500, 3000}, {2250, 3000}};
  return b;
}

// A scenario: `robots` of table 5.1 running `behaviour`, the ball at
// position `ball` (1-based; 0 = out of sight in a carpet corner), noise on.
inline std::string scenario(int robots, const std::string& behaviour, int ball, uint64_t seed, double duration,
                            const std::string& extra = "") {
  char buf[256];
  std::string s = "duration: " + std::to_string(duration) + "\nseed: " + std::to_string(seed) + "\nnoise: on\n";
  if (ball > 0) {
    std::snprintf(buf, sizeof buf, "ball: {x: %.3f, y: %.3f}\n", table52()[ball - 1].first / 1000,
                  table52()[ball - 1].second / 1000);
    s += buf;
  } else {
    // The world always has a ball and it must lie on the carpet: the far
    // corner of the border strip, 2.6 m from the nearest search point
    // (-3, 2) m and so beyond the detector's 2.5 m range from it.
    s += "ball: {x: -5.1, y: 3.6}\n";
  }
  s += "robots:\n";
  for (int i = 0; i < robots; ++i) {
    const Start& st = table51()[i];
    std::snprintf(buf, sizeof buf, "  - {team: 19, player: %d, x: %.3f, y: %.3f, theta: %.4f, behaviour: %s}\n",
                  st.player, st.x / 1000, st.y / 1000, st.theta, behaviour.c_str());
    s += buf;
  }
  return s + extra;
}

struct Found {
  bool truth = false;  // ground truth: the oracle's frame holds a ball detection, torso within 300 mm
  bool board = false;  // the robot's Blackboard: ball seen this frame, estimate within 300 mm
  int robot = -1;
};

// Robot i by ground truth and by its own Blackboard, between ticks.
inline Found foundBy(simswift::runner::Runner& r, int i) {
  Found f;
  f.robot = i;
  const auto& board = r.programs().program(i)->board();
  const agent::blackboard::FrameInfo frame = board.frame.read();
  bool detected = false;
  for (int k = 0; k < frame.num_observations; ++k)
    detected = detected || frame.observations[k].type == common::libagent::ObservationType::Ball;
  const simswift::game::PlanarPose p = simswift::game::robotPose(r.world(), i);
  const Eigen::Vector3d b = r.world().ballPosition();
  const double d_truth = std::hypot(b.x() - p.x, b.y() - p.y);  // m
  f.truth = detected && d_truth <= 0.300;
  const agent::blackboard::BallEstimate e = board.ball.read();
  f.board = e.valid && e.seen_this_frame && std::hypot(e.rr_x, e.rr_y) <= 300.0;
  return f;
}

struct FindTimes {
  std::optional<double> truth;  // s: first frame a robot found it by ground truth
  std::optional<double> board;  // s: first frame a robot's Blackboard says so
  int robot = -1;               // who (ground truth)
  bool both() const { return truth && board; }
};

// Runs until both tests have held (each at some camera frame, any robot) or
// `limit` s of simulated time.
inline FindTimes timeToFind(simswift::runner::Runner& r, double limit) {
  FindTimes t;
  r.start();
  const int64_t end = static_cast<int64_t>(std::llround(limit / 0.01));
  int64_t last_frame = -1;
  while (r.ticks() < end && !t.both()) {
    r.tick();
    const int64_t frame = r.programs().program(0)->board().frame.read().frame_index;
    if (frame == last_frame) continue;  // a new camera frame only
    last_frame = frame;
    for (int i = 0; i < r.numRobots(); ++i) {
      const Found f = foundBy(r, i);
      if (f.truth && !t.truth) {
        t.truth = r.world().time();
        t.robot = i;
      }
      if (f.board && !t.board) t.board = r.world().time();
    }
  }
  return t;
}

}  // namespace findball_harness
