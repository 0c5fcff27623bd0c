// Prints docs/behaviour.md's kinematic find-ball table: time to find a ball at
// table 5.2's positions 1-5 (s) from table 5.1's starts, mean [min, max]
// over start-pose seeds 1..5; 400 = not found within 400 s. A table
// printer, not a test (it asserts nothing); the closed-loop logic tests
// that do assert are tests/agent/behaviour/test_findball_closed_loop.cpp.
//   build/tools/findball-times
#include <algorithm>
#include <cstdio>

#include "harness/Table51Setup.hpp"

using namespace agent::behaviour;
using namespace agent::behaviour::table51;

int main() {
  // Kinematic times (s) for docs/behaviour.md: mean [min, max] over start-pose
  // seeds 1..5; 400 = not found within 400 s.
  for (int robots : {1, 3})
    for (auto kind : {BehaviourKind::FINDBALL_2016, BehaviourKind::FINDBALL_2017}) {
      std::printf("%s, %d robot(s):", kind == BehaviourKind::FINDBALL_2016 ? "2016" : "2017", robots);
      for (const Point2& b : kBalls) {
        double sum = 0, lo = 1e9, hi = 0;
        for (unsigned seed = 1; seed <= 5; ++seed) {
          const double t = std::min(400.0, findTime(kind, robots, b, 400.0, seed));
          sum += t;
          lo = std::min(lo, t);
          hi = std::max(hi, t);
        }
        std::printf("  %5.1f [%5.1f, %5.1f]", sum / 5, lo, hi);
      }
      std::printf("\n");
    }
  return 0;
}
