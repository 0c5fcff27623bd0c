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

#include "FindBallHarness.hpp"

using simswift::runner::Runner;
using simswift::runner::Scenario;

namespace {
constexpr double kMirrorDuration = 60;  // s
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
// Starts with robots in the opponent's half (start sets 3 and 4 of
// tools/findball_random_starts.py --seed 25): a robot placed there keeps its
// sideline-entry (own half) belief and its localisation settles on the
// field's mirror twin, so its packets put it on the other half and only the
// sonars keep a teammate from walking into it.
const Start3 kMirrorStarts[] = {
    {{2.73, 0.51, -0.79}, {-1.56, -0.36, 1.76}, {-0.476, -0.037, 0.809}},
    {{-0.37, 1.02, -3.18}, {-0.12, -0.84, -2.28}, {-1.762, -2.738, 1.159}},
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

// The mirror starts: no contact fall with the sonars; without them (the
// same runs, skills: {sonar_avoid: false}) some robot is knocked over, so
// the set tells the two apart. DISABLED: as measured (2026-11-25) it does
// not hold yet: seed 404 gave 1 contact fall with the sonars and 0 without,
// seed 405 0 and 0 (docs/experiment.md, "What is left"). Kept so the claim
// has its test once a start set that discriminates is found.
TEST(TeammatesApartPhysics, DISABLED_SonarsKeepMislocalisedTeammatesApart) {
  int with = 0, without = 0, seed = 404;
  for (const Start3& s : kMirrorStarts) {
    for (int f : contactFalls(s, seed, kMirrorDuration, "{}")) with += f;
    for (int f : contactFalls(s, seed, kMirrorDuration, "{sonar_avoid: false}")) without += f;
    ++seed;
  }
  EXPECT_EQ(with, 0);
  EXPECT_GT(without, 0);
}
