// A team's walk unit-tested in physics with simswift's walk test kit
// (simswift/WalkTest.hpp): plain GoogleTests, no threads, no shared memory.
// The walk under test is the reference robot code's Walk2014Generator
// (simswift::agent, installed beside the API for teams that want it); a team
// links its own walk in its place. simswift's value types have libagent's
// layout, so the walk's own types map by memcpy.
//
// The seeds below were not used to choose the thresholds (the thresholds
// are the walk's targets; the kit was tried on seeds 1-20).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "common/libagent/AgentShared.hpp"
#include "agent/motion/Walk2014Generator.hpp"
#include "simswift/WalkTest.hpp"

namespace {

// The team's walk behind the kit's Gait: the command becomes the walk's
// request, the libagent types cross by memcpy.
struct TeamWalk {
  agent::motion::Walk2014Generator walk;

  void tick(const simswift::WalkCommand& c, const simswift::SensorValues& s, simswift::JointValues& j) {
    common::libagent::SensorValues in;
    common::libagent::JointValues out;
    static_assert(sizeof in == sizeof s && sizeof out == sizeof j, "libagent layout");
    std::memcpy(&in, &s, sizeof in);
    std::memcpy(&out, &j, sizeof out);
    walk.setRequest(c.walk, {c.forward, c.left, c.turn});
    walk.tick(in, c.tick, out);  // s: the robot's tick, as the kit gives it (10 ms on a V5, 12 ms on a V6)
    std::memcpy(&j, &out, sizeof j);
  }
};

// The spread of one figure over seeds, printed beside the test.
struct Spread {
  double lo = 1e9, hi = -1e9, sum = 0;
  int n = 0;
  void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v), sum += v, ++n; }
  void print(const char* what) const { std::printf("%s: mean %.3f, range %.3f-%.3f over %d seeds\n", what, sum / n, lo, hi, n); }
};

}  // namespace

// The ten-line test: 200 mm/s forward reaches 90 % of the command (2 s to
// start, 6 s measured from the true pose) and does not fall, on 20 seeds.
TEST(TeamWalk, Reaches90PercentOf200ForwardOverTwentySeeds) {
  Spread ratio;
  for (uint64_t seed = 501; seed <= 520; ++seed) {
    TeamWalk walk;  // fresh per seed
    simswift::WalkTest test(seed, [&](const simswift::WalkCommand& c, const simswift::SensorValues& s,
                                      simswift::JointValues& j) { walk.tick(c, s, j); });
    const simswift::WalkFigures f = test.walk({200, 0, 0});
    EXPECT_GE(f.forward_ratio, 0.9) << "seed " << seed << ": " << f.summary();
    EXPECT_EQ(f.falls, 0) << "seed " << seed << ": " << f.summary();
    ratio.add(f.forward_ratio);
  }
  ratio.print("forward 200 mm/s achieved / commanded (seeds 501-520)");
}

// Sideways and turning on the spot reach 85 % of the command, upright.
TEST(TeamWalk, SideStepsAndTurnsWithin15Percent) {
  Spread left, turn;
  for (uint64_t seed = 521; seed <= 525; ++seed) {
    TeamWalk walk;
    simswift::WalkTest test(seed, [&](const simswift::WalkCommand& c, const simswift::SensorValues& s,
                                      simswift::JointValues& j) { walk.tick(c, s, j); });
    const simswift::WalkFigures f = test.walk({0, 150, 0});
    std::printf("seed %d: %s\n", static_cast<int>(seed), f.summary().c_str());
    EXPECT_GE(f.left_ratio, 0.85) << f.summary();
    EXPECT_EQ(f.falls, 0) << f.summary();
    left.add(f.left_ratio);
  }
  for (uint64_t seed = 526; seed <= 530; ++seed) {
    TeamWalk walk;
    simswift::WalkTest test(seed, [&](const simswift::WalkCommand& c, const simswift::SensorValues& s,
                                      simswift::JointValues& j) { walk.tick(c, s, j); });
    const simswift::WalkFigures f = test.walk({0, 0, 0.6});
    std::printf("seed %d: %s\n", static_cast<int>(seed), f.summary().c_str());
    EXPECT_GE(f.turn_ratio, 0.85) << f.summary();
    EXPECT_EQ(f.falls, 0) << f.summary();
    turn.add(f.turn_ratio);
  }
  left.print("left 150 mm/s achieved / commanded (seeds 521-525)");
  turn.print("turn 0.6 rad/s achieved / commanded (seeds 526-530)");
}

// Walking and turning, then stopping: no fall over 20 seeds (the sensor
// noise, and with it every step, differs per seed).
TEST(TeamWalk, DoesNotFallWalkingTurningAndStoppingOverTwentySeeds) {
  for (uint64_t seed = 200; seed < 220; ++seed) {
    TeamWalk walk;
    simswift::WalkTest test(seed, [&](const simswift::WalkCommand& c, const simswift::SensorValues& s,
                                      simswift::JointValues& j) { walk.tick(c, s, j); });
    test.command({250, 0, 0.2});
    test.run(4.0);
    test.command({0, 0, 0, false});  // stand
    test.run(1.5);
    EXPECT_EQ(test.sample().falls, 0) << "seed " << seed;
  }
}

// A 1 N*s shove from behind while walking (~0.19 m/s to the 5.3 kg body):
// the robot stays up and keeps walking forward.
TEST(TeamWalk, RecoversFromAPushWhileWalking) {
  TeamWalk walk;
  simswift::WalkTest test(301, [&](const simswift::WalkCommand& c, const simswift::SensorValues& s,
                                   simswift::JointValues& j) { walk.tick(c, s, j); });
  test.command({250, 0, 0});
  test.run(3.0);
  test.robot().push(1.0, 0.0);
  test.run(3.0);
  const simswift::WalkFigures f = test.walk({250, 0, 0}, 0.0, 2.0);
  EXPECT_EQ(test.sample().falls, 0) << f.summary();
  EXPECT_GT(f.forward, 150) << f.summary();  // mm/s: still walking
}

// A trace of a start, 3 s of walking and a stop, plotted: the CSV (per tick:
// true pose, commanded and measured joints, FSRs, gyroscope) and the PNG are
// left in the build folder to look at.
TEST(TeamWalk, TraceAndPlot) {
  TeamWalk walk;
  simswift::WalkTest test(302, [&](const simswift::WalkCommand& c, const simswift::SensorValues& s,
                                   simswift::JointValues& j) { walk.tick(c, s, j); });
  test.trace("team_walk_trace.csv");
  test.command({200, 0, 0});
  test.run(3.0);
  test.command({0, 0, 0, false});
  test.run(1.0);
  test.stopTrace();
  std::string message;
  EXPECT_TRUE(simswift::plotTrace("team_walk_trace.csv", "team_walk_trace.png", &message)) << message;
  EXPECT_EQ(test.sample().falls, 0);
}
