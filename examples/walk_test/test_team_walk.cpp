// A team's walk unit-tested in physics: plain GoogleTests, no threads, no
// shared memory. The walk under test is the reference robot code's
// Walk2014Generator (simswift::agent, installed beside the API for teams
// that want it); a team links its own walk in its place. simswift's value
// types have libagent's layout, so the walk's own types map by memcpy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

#include "agent/libagent/AgentShared.hpp"
#include "agent/motion/Walk2014Generator.hpp"
#include "simswift/Simulation.hpp"

namespace {

constexpr double kTick = 0.01;     // s: the motion tick
constexpr double kForward = 250;   // mm/s commanded

// Robot 0 at the own goal area facing the far goal, no ball: room for 4 m.
std::string scenario(int seed) {
  return "duration: 60\nseed: " + std::to_string(seed) + "\nnoise: on\nball: none\n"
         "robots:\n  - {team: 19, player: 1, x: -3.0, y: 0.0, theta: 0.0}\n";
}

struct TeamWalk {
  agent::motion::Walk2014Generator walk;

  void drive(simswift::Simulation& sim, int robot) {
    sim.robot(robot).setController([this](const simswift::SensorValues& s, simswift::JointValues& j) {
      agent::libagent::SensorValues in;
      agent::libagent::JointValues out;
      static_assert(sizeof in == sizeof s && sizeof out == sizeof j, "libagent layout");
      std::memcpy(&in, &s, sizeof in);
      std::memcpy(&out, &j, sizeof out);
      walk.tick(in, kTick, out);
      std::memcpy(&j, &out, sizeof j);
    });
  }
};

// Walks 2 m forward within 10 % of the command: after a 2 s start, 8 s at
// 250 mm/s must cover 2 m +- 0.2 m, upright, within 0.3 m of the line, on
// each of 10 seeds (the noise, and with it every step, differs per seed).
TEST(TeamWalk, Walks2MetresForwardWithin10PercentOfCommand) {
  double least = 1e9, most = 0;
  for (int seed = 101; seed <= 110; ++seed) {
    simswift::Simulation sim = simswift::Simulation::fromYaml(scenario(seed), "walk.yaml");
    TeamWalk team;
    team.drive(sim, 0);
    team.walk.setRequest(true, {kForward, 0, 0});
    sim.run(2.0);
    const simswift::Pose start = sim.robot(0).pose();
    const double seconds = 2000.0 / kForward;
    sim.run(seconds);
    const double walked = sim.robot(0).pose().x - start.x;  // m, field x = the robot's heading
    least = std::min(least, walked);
    most = std::max(most, walked);
    EXPECT_NEAR(walked, 2.0, 0.2) << "seed " << seed;
    EXPECT_NEAR(sim.robot(0).pose().y, start.y, 0.3) << "seed " << seed;
    EXPECT_FALSE(sim.robot(0).fallen()) << "seed " << seed;
  }
  std::printf("walked %.3f-%.3f m in 8 s at %.0f mm/s commanded (seeds 101-110)\n", least, most, kForward);
}

// Walking and turning, then stopping: no fall over 20 seeds (the sensor
// noise, and with it every step, differs per seed).
TEST(TeamWalk, DoesNotFallOverTwentySeeds) {
  for (int seed = 200; seed < 220; ++seed) {
    simswift::Simulation sim = simswift::Simulation::fromYaml(scenario(seed), "walk.yaml");
    TeamWalk team;
    team.drive(sim, 0);
    team.walk.setRequest(true, {kForward, 0, 0.2});
    sim.run(4.0);
    team.walk.setRequest(false, {});
    sim.run(1.5);
    EXPECT_EQ(sim.robot(0).falls(), 0) << "seed " << seed;
  }
}

// A 1 N*s shove from behind while walking (~0.19 m/s to the 5.3 kg body):
// the robot stays up and keeps walking forward.
TEST(TeamWalk, RecoversFromAPushWhileWalking) {
  simswift::Simulation sim = simswift::Simulation::fromYaml(scenario(301), "walk.yaml");
  TeamWalk team;
  team.drive(sim, 0);
  team.walk.setRequest(true, {kForward, 0, 0});
  sim.run(3.0);
  sim.robot(0).push(1.0, 0.0);
  sim.run(3.0);
  EXPECT_EQ(sim.robot(0).falls(), 0);
  const double x = sim.robot(0).pose().x;
  sim.run(2.0);
  EXPECT_GT(sim.robot(0).pose().x - x, 0.3);  // m in 2 s: still walking
}

}  // namespace
