// The robot program's Perception modules in the loop: a frame at 30 Hz for
// every builtin robot with nothing rendered; a scripted robot stands while
// penalised and walks again when released; teammates' reports reach each
// other's Team section through the simulated network.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/game/Sideline.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"

using simswift::runner::Runner;
using simswift::runner::Scenario;
namespace bb = agent::blackboard;

TEST(RunnerPerception, EveryRobotGetsThirtyFramesASecondWithoutImages) {
  Runner r(Scenario::parse("duration: 2\nseed: 4\nnoise: off\nrobots:\n"
                           "  - {team: 19, player: 1, x: -1}\n"
                           "  - {team: 19, player: 2, x: -2, actions: [{t: 0.5, action: walk, forward: 100}]}\n",
                           "p.yaml"));
  r.start();
  while (r.ticks() < 200) r.tick();
  // Frames where floor(t * 30) advances: 0..60 over ticks 0.01 .. 2.00 s.
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(r.programs().program(i)->perceptionFrames(), 61) << i;
    EXPECT_EQ(r.images(i), nullptr);
  }
}

TEST(RunnerPerception, ScriptedRobotStandsWhilePenalisedAndWalksWhenReleased) {
  Runner r(Scenario::parse("duration: 6\nseed: 5\nnoise: on\nrobots:\n"
                           "  - {team: 19, player: 2, x: -2.5, y: 0, actions: [{t: 0.2, action: walk, forward: 200}]}\n"
                           "game:\n  penalties: [{t: 2.0, robot: 0, penalty: player_pushing, duration: 2.0}]\n",
                           "pen.yaml"));
  r.start();
  auto body = [&] { return r.programs().program(0)->board().motion_request.read().body.type; };
  auto x = [&] { return simswift::game::robotPose(r.world(), 0).x; };
  while (r.ticks() < 190) r.tick();  // walking before the penalty
  EXPECT_EQ(body(), bb::ActionType::WALK);
  while (r.ticks() < 230) r.tick();  // 2.3 s: penalised, placed at the sideline
  EXPECT_TRUE(r.programs().program(0)->board().game.read().penalised);
  EXPECT_EQ(body(), bb::ActionType::STAND);
  const double x_pen = x();
  while (r.ticks() < 390) r.tick();  // still penalised at 3.9 s: it has not walked
  EXPECT_EQ(body(), bb::ActionType::STAND);
  EXPECT_NEAR(x(), x_pen, 0.08);  // m: the walk stopping, not walking on (200 mm/s would be 0.3 m)
  while (r.ticks() < 600) r.tick();  // released at 4 s
  EXPECT_FALSE(r.programs().program(0)->board().game.read().penalised);
  EXPECT_EQ(body(), bb::ActionType::WALK);
}

TEST(RunnerPerception, TeammatesHearEachOther) {
  Runner r(Scenario::parse("duration: 2\nseed: 6\nnoise: off\nrobots:\n"
                           "  - {team: 19, player: 1, x: -2}\n"
                           "  - {team: 19, player: 3, x: -1}\n"
                           "  - {team: 5, player: 1, x: 2, theta: 3.14159}\n",
                           "team.yaml"));
  r.start();
  while (r.ticks() < 200) r.tick();
  const bb::TeamInfo a = r.programs().program(0)->board().team.read(), b = r.programs().program(1)->board().team.read();
  const bb::TeamInfo c = r.programs().program(2)->board().team.read();
  EXPECT_TRUE(a.mates[3].valid);
  EXPECT_TRUE(b.mates[1].valid);
  EXPECT_GE(a.received, 8);  // 5 Hz for 2 s
  EXPECT_EQ(a.malformed, 0);
  EXPECT_EQ(c.received, 0);  // alone in its team
  // Heard recently (s of simulated time).
  EXPECT_LE(a.mates[3].received, 2.0);
  EXPECT_GT(a.mates[3].received, 1.5);
}
