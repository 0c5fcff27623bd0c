// A team's unit tests of its motion code in physics: plain GoogleTests, no
// threads, no shared memory. Each test builds a simulation from YAML text
// (the model and field come from the installed package's data) and drives
// robot 0 with the team's code, called once per tick (10 ms on a V5).
#include <gtest/gtest.h>

#include <string>

#include "simswift/Simulation.hpp"
#include "team_motion.hpp"

namespace {

std::string field(int seed) {
  return "duration: 10\nseed: " + std::to_string(seed) + "\nnoise: on\nrobots:\n  - {team: 5, player: 1, x: 0, y: 0}\n";
}

simswift::Simulation withTeamMotion(int seed, team::StandMotion& motion) {
  simswift::Simulation sim = simswift::Simulation::fromYaml(field(seed), "team.yaml");
  sim.robot(0).setController(
      [&motion](const simswift::SensorValues& s, simswift::JointValues& j) { motion.tick(s, j); });
  return sim;
}

}  // namespace

// Physics fact: standing still, the eight FSRs (kg) sum to the NAO's mass
// (5.305 kg, Aldebaran's V5 datasheet), within 5 %.
TEST(TeamMotion, StandsOnItsFeetWithItsWholeMass) {
  team::StandMotion motion;
  simswift::Simulation sim = withTeamMotion(1, motion);
  sim.run(2.0);
  double kg = 0;  // mean over 0.5 s: the sensor noise and the stance's sway average out
  for (int k = 0; k < 50; ++k) {
    sim.step();
    const simswift::SensorValues s = sim.robot(0).sensors();
    for (int f = simswift::api::LFsrFrontLeft; f <= simswift::api::LFsrRearRight; ++f) kg += s.sensors[f] / 50;
    for (int f = simswift::api::RFsrFrontLeft; f <= simswift::api::RFsrRearRight; ++f) kg += s.sensors[f] / 50;
  }
  EXPECT_NEAR(kg, 5.305, 0.05 * 5.305);
}

// Does not fall over 20 seeds (the sensor noise differs per seed) in 10 s.
TEST(TeamMotion, DoesNotFallOverTwentySeeds) {
  for (int seed = 100; seed < 120; ++seed) {
    team::StandMotion motion;
    simswift::Simulation sim = withTeamMotion(seed, motion);
    sim.run(10.0);
    EXPECT_FALSE(sim.robot(0).fallen()) << "seed " << seed;
    EXPECT_EQ(sim.robot(0).falls(), 0) << "seed " << seed;
  }
}

// A shove of 1 N*s (0.19 m/s of the body's 5.3 kg) from behind: still up 3 s later.
TEST(TeamMotion, RecoversFromAPush) {
  team::StandMotion motion;
  simswift::Simulation sim = withTeamMotion(7, motion);
  sim.run(1.0);
  sim.robot(0).push(1.0, 0.0);
  sim.run(3.0);
  EXPECT_FALSE(sim.robot(0).fallen());
  EXPECT_GT(sim.robot(0).pose().z, 0.25);  // torso origin height, m: standing
}
