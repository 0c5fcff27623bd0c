// PHYSICS: robots that enter on the touch lines of their own half keep the
// true side of the point-symmetric field. Trial 170 of
// scenarios/findball_random_starts_touchline_2514.yaml (three 2017 searchers,
// run as `simswift experiment --trial 170` runs it): player 4 enters at
// (-0.33, 3.00) m, 0.33 m from the halfway line, where its mirror twin
// (0.33, -3.00) m is as near its entry belief as the truth. Before the
// localisation's own-half bound (agent/localisation/Localiser.hpp) it settled
// on the twin within a second (6.0 m off at 1 s; traced with
// tools/findball-trace, 2026-11-26) and walked into a teammate at 63 s.
// Every robot must be within 400 mm of its true position from 1 s to 5 s
// of play.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "agent/program/RobotProgram.hpp"
#include "sim/programs/Programs.hpp"
#include "app/experiment/BehaviourHooks.hpp"
#include "app/experiment/Experiment.hpp"
#include "app/experiment/Trial.hpp"
#include "sim/world/World.hpp"

using namespace simswift;
using namespace simswift::experiment;

TEST(HalfwayEntryPhysics, RobotsEnteringBesideTheHalfwayLineKeepTheirSide) {
  const Experiment e =
      Experiment::loadFile(std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/findball_random_starts_touchline_2514.yaml");
  const TrialSpec t = trialSpec(e, 170);
  const experiment::Setup& setup = e.setups[t.setup];
  ASSERT_EQ(setup.name, "2017-s4");
  const std::unique_ptr<runner::Runner> owned = startTrial(e, t.index, behaviourHooks());
  runner::Runner& run = *owned;
  const int n = static_cast<int>(setup.robots.size());
  const int64_t play = playTick(e);
  const int64_t per_s = common::nao::ticksIn(1.0);
  while (run.ticks() < play + 5 * per_s) {
    run.tick();
    const int64_t since = run.ticks() - play;
    if (since < per_s || since % 10 != 0) continue;
    for (int i = 0; i < n; ++i) {
      const auto truth = run.world().robot(i).torsoPose();  // m
      const agent::blackboard::FieldPose est = run.programs().program(i)->board().localisation.read().pose;  // mm
      const double err = std::hypot(truth.x * 1000 - est.x, truth.y * 1000 - est.y);
      ASSERT_LT(err, 400) << "player " << setup.robots[i].player << " at " << since * kTickSeconds << " s: true ("
                          << truth.x << ", " << truth.y << ") m, believed (" << est.x << ", " << est.y << ") mm";
    }
  }
}
