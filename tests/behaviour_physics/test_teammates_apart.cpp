// PHYSICS: three 2017 searchers from seeded random starts (the starts are
// fixed here, drawn once with tools/findball_random_starts.py's rule:
// anywhere on the field, 0.8 m apart, any heading) never knock each other
// over. The simulator counts a fall as one after a robot contact when the
// robot touched another robot within 2 s before (runner::FallDetector).
// The ball lies out of sight in a carpet corner, so they search all along.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "harness/FindBallHarness.hpp"

using simswift::runner::Runner;
using simswift::runner::Scenario;

namespace {
struct Start3 {
  double x[3], y[3], theta[3];  // m, m, rad
};
// Three start sets; the first two put two robots facing each other's way
// within 1.5 m (the case that made teammates meet), the third is spread.
const Start3 kStarts[] = {
    {{-1.22, 4.07, 0.71}, {-0.17, 0.76, -0.48}, {-2.488, -2.524, -1.952}},
    {{0.40, 1.60, -2.50}, {0.90, 0.30, -1.80}, {-0.30, 2.80, 0.60}},
    {{-3.60, 2.00, 3.20}, {-2.10, 2.40, 1.00}, {0.80, -2.50, 2.00}},
};
// Contact falls per robot of three 2017 searchers from `s` for `duration` s.
std::vector<int> contactFalls(const Start3& s, int seed, double duration, const char* skills) {
  std::string text = "duration: " + std::to_string(duration) + "\nseed: " + std::to_string(seed) +
                     "\nnoise: on\nball: {x: -5.1, y: 3.6}\nrobots:\n";
  for (int i = 0; i < 3; ++i) {
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "  - {team: 19, player: %d, x: %.2f, y: %.2f, theta: %.3f, behaviour: {kind: findball2017, "
                  "skills: %s}}\n",
                  2 + i, s.x[i], s.y[i], s.theta[i], skills);
    text += buf;
  }
  Runner r(Scenario::parse(text, "apart.yaml"));
  simswift::runner::RunOptions o;
  o.progress = false;
  const simswift::runner::RunStats st = r.run(o);
  std::vector<int> out;
  for (size_t i = 0; i < st.robots.size(); ++i) {
    std::printf("seed %d robot %zu (skills %s): falls %d, after robot contact %d\n", seed, 2 + i, skills,
                st.robots[i].falls, st.robots[i].contact_falls);
    out.push_back(st.robots[i].contact_falls);
  }
  return out;
}
}  // namespace

TEST(TeammatesApartPhysics, ThreeSearchersFromRandomStartsNeverKnockEachOtherOver) {
  int seed = 401;
  for (const Start3& s : kStarts) {
    const std::vector<int> f = contactFalls(s, seed, 45, "{}");
    ASSERT_EQ(f.size(), 3u);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(f[i], 0) << "seed " << seed << " player " << 2 + i;
    ++seed;
  }
}
