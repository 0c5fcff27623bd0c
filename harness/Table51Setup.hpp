// Table 5.1's starts and table 5.2's balls 1-5 for the FindBall behaviours
// in the kinematic world (KinematicWorld.hpp): shared by the closed-loop
// logic tests (tests/agent/behaviour) and tools/findball_times.cpp, which
// prints docs/behaviour.md's table.
#pragma once

#include <algorithm>
#include <cstdint>

#include "common/random/DeriveSeed.hpp"
#include "common/random/Random.hpp"
#include "harness/KinematicWorld.hpp"

namespace agent::behaviour::table51 {

// Table 5.1's robot starts (on the touch line, facing into the field).
inline const Pose2 kRobot2{-3250, 3000, -kPi / 2};
inline const Pose2 kRobot3{-2000, -3000, kPi / 2};
inline const Pose2 kRobot4{-1750, 3000, -kPi / 2};
// Table 5.2's ball positions 1..5.
inline const Point2 kBalls[5] = {{2250, 0}, {4000, -2500}, {4000, 2500}, {4500, 3000}, {2250, 3000}};

inline BehaviourConfig config(BehaviourKind k) {
  BehaviourConfig c;
  c.kind = k;
  return c;
}

// Robot `player`'s start pose `p` jittered by the seed (0 = table 5.1
// exactly): x and y by up to +-150 mm, theta by up to +-0.3 rad, uniform
// (y kept on the field). The draws are the project's own (Random, a fixed
// algorithm: the same on every compiler and standard library), from the one
// seed recipe: deriveSeed(deriveSeed(seed, kTable51Start), player), in the
// order x, y, theta. The kinematic world has no noise of its own.
inline Pose2 jitter(Pose2 p, int player, uint64_t seed) {
  if (seed == 0) return p;
  namespace cr = common::random;
  cr::Random rng(cr::deriveSeed(cr::deriveSeed(seed, cr::seed_tag::kTable51Start), static_cast<uint64_t>(player)));
  p.x += rng.uniform(-150.0, 150.0);  // mm
  p.y = std::clamp(p.y + rng.uniform(-150.0, 150.0), -3000.0, 3000.0);
  p.theta += rng.uniform(-0.3, 0.3);  // rad
  return p;
}

inline double findTime(BehaviourKind kind, int robots, Point2 ball, double limit = 180.0,
                uint64_t seed = 0) {
  kin::World w;
  w.ball = ball;
  w.add(2, jitter(kRobot2, 2, seed), config(kind));
  if (robots == 3) {
    w.add(3, jitter(kRobot3, 3, seed), config(kind));
    w.add(4, jitter(kRobot4, 4, seed), config(kind));
  }
  return w.runUntilFound(limit);
}

}  // namespace agent::behaviour::table51
