// The scenario's team_comms: and game: blocks, and both in a run: packets
// sent by robot code through the team link reach teammates, a penalised
// robot waits on the sideline and comes back, the robot code reads it all.
#include <gtest/gtest.h>

#include <cmath>

#include "agent/comms/GameStateReader.hpp"
#include "agent/comms/TeamReceiver.hpp"
#include "agent/comms/TeamSender.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"
#include "tests/support/ConfigErrors.hpp"

using simswift::ConfigError;
using simswift::runner::Runner;
using simswift::runner::Scenario;
namespace ac = agent::comms;
namespace al = common::libagent;

namespace {
std::string scenarioError(const std::string& yaml) {
  return simswift::testing::configError([&] { Scenario::parse(yaml, "s.yaml"); });
}
const char* kRobots = "robots:\n  - {team: 0, player: 2}\n  - {team: 0, player: 3, x: 1}\n";
}  // namespace

TEST(GameScenario, DefaultsWithoutTheBlocks) {
  const Scenario s = Scenario::parse(kRobots, "s.yaml");
  EXPECT_EQ(s.team_comms.loss, 0);
  EXPECT_EQ(s.team_comms.delay_ms, 0);
  EXPECT_EQ(s.team_comms.budget, 0);
  EXPECT_EQ(s.game.initial_state, simswift::game::GameStateValue::Playing);
  EXPECT_TRUE(s.game.timeline.empty());
}

TEST(GameScenario, BlocksParse) {
  const Scenario s = Scenario::parse(std::string(kRobots) +
                                         "team_comms: {loss: 0.25, delay_ms: 120, budget: 1200}\n"
                                         "game:\n"
                                         "  state: initial\n"
                                         "  kickoff_team: 1\n"
                                         "  on_unpenalise: sideline\n"
                                         "  timeline: [{t: 1, state: ready}, {t: 2, state: playing, kickoff_team: 0}]\n"
                                         "  penalties: [{t: 0.5, robot: 1, penalty: player_pushing, duration: 45}]\n",
                                     "s.yaml");
  EXPECT_DOUBLE_EQ(s.team_comms.loss, 0.25);
  EXPECT_DOUBLE_EQ(s.team_comms.delay_ms, 120);
  EXPECT_EQ(s.team_comms.budget, 1200);
  EXPECT_EQ(s.game.initial_state, simswift::game::GameStateValue::Initial);
  EXPECT_EQ(s.game.kickoff_team, 1);
  EXPECT_EQ(s.game.on_unpenalise, simswift::game::GameConfig::Return::Sideline);
  ASSERT_EQ(s.game.timeline.size(), 2u);
  EXPECT_EQ(s.game.timeline[1].kickoff_team, 0);
  ASSERT_EQ(s.game.penalties.size(), 1u);
  EXPECT_EQ(s.game.penalties[0].robot, 1);
  EXPECT_EQ(s.game.penalties[0].penalty, simswift::game::Penalty::PlayerPushing);
  EXPECT_DOUBLE_EQ(s.game.penalties[0].duration_s, 45);
}

TEST(GameScenario, ErrorsNameFileLineAndField) {
  const std::string r = kRobots;
  EXPECT_NE(scenarioError(r + "team_comms: {loss: 1.5}\n").find("s.yaml:4: team_comms.loss: must be"), std::string::npos)
      << scenarioError(r + "team_comms: {loss: 1.5}\n");
  EXPECT_NE(scenarioError(r + "team_comms: {delay: 10}\n").find("s.yaml:4: unknown key 'delay' in team_comms"), std::string::npos);
  EXPECT_NE(scenarioError(r + "team_comms: {budget: -3}\n").find("team_comms.budget"), std::string::npos);
  const std::string bad_robot = scenarioError(r + "game:\n  penalties: [{t: 1, robot: 2}]\n");
  EXPECT_NE(bad_robot.find("s.yaml:5: game.penalties[0].robot: no robot 2"), std::string::npos) << bad_robot;
  const std::string bad_state = scenarioError(r + "game:\n  timeline: [{t: 1, state: halftime}]\n");
  EXPECT_NE(bad_state.find("game.timeline[0].state: expected one of initial"), std::string::npos) << bad_state;
  EXPECT_NE(scenarioError(r + "game:\n  timeline: [{t: 2, state: set}, {t: 1, state: playing}]\n")
                .find("game.timeline[1].t: timeline entries must be in time order"),
            std::string::npos);
  EXPECT_NE(scenarioError(r + "game:\n  penalties: [{t: 1, robot: 0, penalty: biting}]\n").find("game.penalties[0].penalty"),
            std::string::npos);
  EXPECT_NE(scenarioError(r + "game:\n  timeline: [{t: 1}]\n").find("needs a state"), std::string::npos);
}

namespace {
// Robot code for the run below: each Perception frame reads the game state,
// drains the inbox and sends at 5 Hz, through the extension objects only.
struct TeamPerception : agent::framework::PerceptionStep {
  Runner* runner;
  int index, team, player;
  ac::TeamSender sender;
  ac::TeamReceiver receiver;
  ac::GameStateReader reader;
  ac::GameState last;
  int64_t penalised_frames = 0;
  TeamPerception(Runner* r, int i, int t, int p)
      : runner(r), index(i), team(t), player(p), sender(t, p), receiver(t, p), reader(t, p) {}
  void step(const al::CameraFrame& f) override {
    ++frames_;
    al::SimExtensions* ext = runner->extensions(index);
    last = reader.read(&ext->game);
    if (last.penalised) ++penalised_frames;
    ac::TeamLinkTransport link(&ext->team);
    receiver.update(link, f.sim_time_us);
    ac::SplMessage m;
    m.pose_x = static_cast<float>(1000 * player);
    sender.maybeSend(link, f.sim_time_us, m);
  }
};
}  // namespace

// 3 robots (team 0: players 2 and 3; team 1: player 2), 4 s, loss 0, 50 ms
// delay; robot 0 penalised from 1 s for 1.5 s.
TEST(GameScenario, RunCarriesPacketsAndPenalties) {
  Scenario s = Scenario::parse(
      "duration: 4\nseed: 3\nnoise: off\n"
      "robots:\n"
      "  - {team: 0, player: 2, x: -1.0, y: 0.5}\n"
      "  - {team: 0, player: 3, x: -1.0, y: -1.0}\n"
      "  - {team: 1, player: 2, x: 1.0, y: 0.0, theta: 3.14159}\n"
      "team_comms: {delay_ms: 50}\n"
      "game:\n  penalties: [{t: 1.0, robot: 0, penalty: request_for_pickup, duration: 1.5}]\n",
      "run.yaml");
  Runner r(s);
  std::vector<TeamPerception*> code;
  for (int i = 0; i < 3; ++i) {
    auto p = std::make_unique<TeamPerception>(&r, i, s.robots[i].team, s.robots[i].player);
    code.push_back(p.get());
    r.programs().setPerceptionStep(i, std::move(p));
  }
  r.start();
  auto pose = [&](int i) { return simswift::game::robotPose(r.world(), i); };
  while (r.ticks() < 150) r.tick();  // 1.5 s: penalised since 1.0 s
  EXPECT_TRUE(r.gameController().penalised(0));
  EXPECT_NEAR(pose(0).x, -3.2, 0.05);
  EXPECT_NEAR(pose(0).y, 3.0, 0.05);
  EXPECT_TRUE(code[0]->last.penalised);
  EXPECT_FALSE(code[1]->last.penalised);
  while (r.ticks() < 300) r.tick();  // 3.0 s: released at 2.5 s
  EXPECT_FALSE(r.gameController().penalised(0));
  EXPECT_NEAR(pose(0).x, -1.0, 0.06);
  EXPECT_NEAR(pose(0).y, 0.5, 0.06);
  EXPECT_TRUE(code[0]->last.mayMove());
  // Penalised for 1.5 s of 30 Hz frames (the state is seen one frame late at most).
  EXPECT_NEAR(code[0]->penalised_frames, 45, 2);
  while (r.ticks() < 400) r.tick();
  // 5 Hz for 4 s: ~20 packets each; teammates hear each other, nobody hears team 1.
  for (TeamPerception* c : code) EXPECT_NEAR(c->sender.sent(), 20, 1);
  EXPECT_GE(code[0]->receiver.teammate(3).packets, 18);
  EXPECT_GE(code[1]->receiver.teammate(2).packets, 18);
  EXPECT_EQ(code[0]->receiver.stats().other_team, 0);
  EXPECT_EQ(code[2]->receiver.stats().received, 0);  // alone in its team
  EXPECT_EQ(code[0]->receiver.teammate(3).last.pose_x, 3000.f);
  EXPECT_LT(code[0]->receiver.secondsSinceHeard(3, 4000000), 0.3);
  EXPECT_EQ(r.teamNetwork().stats().sent, code[0]->sender.sent() + code[1]->sender.sent() + code[2]->sender.sent());
  r.shutdown();
}

namespace {
// Packets each robot heard in a 3 s run with 40 % loss: the same seed gives
// the same counts, whatever the thread timing.
std::vector<int64_t> heardCounts(uint64_t seed) {
  Scenario s = Scenario::parse("duration: 3\nseed: " + std::to_string(seed) +
                                   "\nnoise: off\n"
                                   "robots:\n"
                                   "  - {team: 0, player: 2, x: -1.0, y: 0.5}\n"
                                   "  - {team: 0, player: 3, x: -1.0, y: -1.0}\n"
                                   "  - {team: 0, player: 4, x: -2.0, y: 0.0}\n"
                                   "team_comms: {loss: 0.4, delay_ms: 20}\n",
                               "det.yaml");
  Runner r(s);
  std::vector<TeamPerception*> code;
  for (int i = 0; i < 3; ++i) {
    auto p = std::make_unique<TeamPerception>(&r, i, s.robots[i].team, s.robots[i].player);
    code.push_back(p.get());
    r.programs().setPerceptionStep(i, std::move(p));
  }
  r.start();
  while (r.ticks() < 300) r.tick();
  std::vector<int64_t> counts;
  for (TeamPerception* c : code)
    for (int p = 2; p <= 4; ++p)
      counts.push_back(p == c->player ? -1 : c->receiver.teammate(p).packets);
  r.shutdown();
  return counts;
}
}  // namespace

TEST(GameScenario, SameSeedSameDeliveriesInARun) {
  const auto a = heardCounts(11), b = heardCounts(11), c = heardCounts(12);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  // 15 packets per sender, 40 % lost: each pair hears about 9.
  for (int64_t n : a)
    if (n >= 0) {
      EXPECT_NEAR(n, 9, 5);
    }
}
