// Table 5.1's starts and table 5.2's balls 1-5 for the FindBall behaviours
// in the kinematic world (KinematicWorld.hpp): shared by the closed-loop
// logic tests (tests/agent/behaviour) and tools/findball_times.cpp, which
// prints docs/behaviour.md's table.
#pragma once

#include <algorithm>
#include <random>

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

// Start poses jittered by the seed (0 = table 5.1 exactly): +-150 mm, +-0.3 rad,
// kept on the field. The kinematic world has no noise of its own.
inline Pose2 jitter(Pose2 p, unsigned seed) {
  if (seed == 0) return p;
  std::mt19937 rng(seed * 7919u + static_cast<unsigned>(p.x));
  std::uniform_real_distribution<double> mm(-150, 150), rad(-0.3, 0.3);
  p.x += mm(rng);
  p.y = std::clamp(p.y + mm(rng), -3000.0, 3000.0);
  p.theta += rad(rng);
  return p;
}

inline double findTime(BehaviourKind kind, int robots, Point2 ball, double limit = 180.0,
                unsigned seed = 0) {
  kin::World w;
  w.ball = ball;
  w.add(2, jitter(kRobot2, seed), config(kind));
  if (robots == 3) {
    w.add(3, jitter(kRobot3, seed), config(kind));
    w.add(4, jitter(kRobot4, seed), config(kind));
  }
  return w.runUntilFound(limit);
}

}  // namespace agent::behaviour::table51
