// The simulator's GameController: a timeline of states, the half's clock,
// penalties with their timers, and what a robot reads from its block.
#include <gtest/gtest.h>

#include <cmath>

#include "agent/comms/GameStateReader.hpp"
#include "sim/game/GameController.hpp"

using namespace simswift::game;
namespace al = common::libagent;

namespace {
constexpr int64_t kTick = 10000;  // us
int64_t us(double s) { return static_cast<int64_t>(std::llround(s * 1e6)); }

// Runs the controller tick by tick up to t_s; collects events.
std::vector<GameEvent> runTo(GameController& gc, int64_t& t, double t_s) {
  std::vector<GameEvent> all;
  while (t < us(t_s)) {
    t += kTick;
    for (const GameEvent& e : gc.update(t)) all.push_back(e);
  }
  return all;
}
}  // namespace

TEST(GameController, TimelineAndTheHalfClock) {
  GameConfig c;
  c.initial_state = GameStateValue::Initial;
  c.half_duration_s = 600;
  c.timeline = {{1.0, GameStateValue::Ready, SecondaryState::Normal, -1},
                {3.0, GameStateValue::Set, SecondaryState::Normal, 1},
                {4.0, GameStateValue::Playing, SecondaryState::Normal, -1},
                {14.0, GameStateValue::Finished, SecondaryState::Normal, -1}};
  GameController gc(c, {{0, 1}, {1, 1}});
  int64_t t = 0;
  gc.update(0);
  EXPECT_EQ(gc.state(), GameStateValue::Initial);
  runTo(gc, t, 0.99);
  EXPECT_EQ(gc.state(), GameStateValue::Initial);
  runTo(gc, t, 1.0);
  EXPECT_EQ(gc.state(), GameStateValue::Ready);
  runTo(gc, t, 1.5);
  al::GameStateBlock b{};
  gc.fill(b);
  EXPECT_EQ(b.secondary_time, 45 - 0);  // ceil(45 - 0.5) = 45
  runTo(gc, t, 2.2);
  gc.fill(b);
  EXPECT_EQ(b.secondary_time, 44);      // ceil(43.8)
  runTo(gc, t, 3.5);
  EXPECT_EQ(gc.state(), GameStateValue::Set);
  EXPECT_EQ(gc.kickoffTeam(), 1);
  EXPECT_DOUBLE_EQ(gc.secsRemaining(), 600);  // not PLAYING yet: the clock stands
  runTo(gc, t, 9.0);
  EXPECT_EQ(gc.state(), GameStateValue::Playing);
  EXPECT_NEAR(gc.secsRemaining(), 595, 1e-6);  // 5 s of PLAYING
  runTo(gc, t, 20.0);
  EXPECT_EQ(gc.state(), GameStateValue::Finished);
  EXPECT_NEAR(gc.secsRemaining(), 590, 1e-6);  // stopped at FINISHED
  gc.fill(b);
  EXPECT_EQ(b.magic, al::kGameStateMagic);
  EXPECT_EQ(b.state, static_cast<uint8_t>(GameStateValue::Finished));
  EXPECT_EQ(b.secs_remaining, 590);
  EXPECT_EQ(b.kickoff_team, 1);
  EXPECT_EQ(b.sim_time_us, us(20.0));
}

TEST(GameController, PenaltyTimersCountDownAndRelease) {
  GameConfig c;  // PLAYING throughout
  c.penalties = {{5.0, 1, Penalty::PlayerPushing, 30.0}};
  GameController gc(c, {{0, 2}, {0, 3}, {1, 3}});
  int64_t t = 0;
  auto ev = runTo(gc, t, 4.99);
  EXPECT_TRUE(ev.empty());
  EXPECT_FALSE(gc.penalised(1));
  ev = runTo(gc, t, 5.0);
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].kind, GameEvent::Kind::Penalised);
  EXPECT_EQ(ev[0].robot, 1);
  EXPECT_NEAR(gc.secsTillUnpenalised(1), 30, 1e-9);
  runTo(gc, t, 20.25);
  EXPECT_NEAR(gc.secsTillUnpenalised(1), 14.75, 1e-9);
  al::GameStateBlock b{};
  gc.fill(b);
  EXPECT_EQ(b.teams[0].players[2].penalty, static_cast<uint8_t>(Penalty::PlayerPushing));  // t0p3
  EXPECT_EQ(b.teams[0].players[2].secs_till_unpenalised, 15);                             // ceil(14.75)
  EXPECT_EQ(b.teams[1].players[2].penalty, 0);                                            // t1p3: other team
  // What the robot code reads from that block.
  const agent::comms::GameState me = agent::comms::GameStateReader(0, 3).read(&b);
  EXPECT_TRUE(me.penalised);
  EXPECT_FALSE(me.mayMove());
  EXPECT_EQ(me.secs_till_unpenalised, 15);
  EXPECT_TRUE(agent::comms::GameStateReader(0, 2).read(&b).mayMove());
  ev = runTo(gc, t, 34.99);
  EXPECT_TRUE(ev.empty());
  ev = runTo(gc, t, 35.0);
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].kind, GameEvent::Kind::Unpenalised);
  EXPECT_FALSE(gc.penalised(1));
  gc.fill(b);
  EXPECT_EQ(b.teams[0].players[2].penalty, 0);
  EXPECT_TRUE(agent::comms::GameStateReader(0, 3).read(&b).mayMove());  // PLAYING releases it
}

// Open-ended penalties (the thesis's experiment: robots wait penalised until
// the ball is placed) end with a `penalty: none` entry.
TEST(GameController, OpenEndedPenaltyEndsWithPenaltyNone) {
  GameConfig c;
  c.penalties = {{0.0, 0, Penalty::RequestForPickup, -1},
                 {0.0, 1, Penalty::RequestForPickup, -1},
                 {2.0, 0, Penalty::None, 0},
                 {3.0, 1, Penalty::None, 0}};
  GameController gc(c, {{0, 2}, {0, 3}});
  auto ev = gc.update(0);
  EXPECT_EQ(ev.size(), 2u);
  EXPECT_TRUE(gc.penalised(0));
  EXPECT_DOUBLE_EQ(gc.secsTillUnpenalised(0), 0);  // open-ended: no estimate
  int64_t t = 0;
  ev = runTo(gc, t, 2.0);
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].robot, 0);
  EXPECT_FALSE(gc.penalised(0));
  EXPECT_TRUE(gc.penalised(1));
  ev = runTo(gc, t, 3.0);
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].robot, 1);
}

TEST(GameController, NamesParse) {
  GameStateValue s;
  EXPECT_TRUE(parseState("set", &s));
  EXPECT_EQ(s, GameStateValue::Set);
  EXPECT_FALSE(parseState("halftime", &s));
  Penalty p;
  EXPECT_TRUE(parsePenalty("illegal_defender", &p));
  EXPECT_EQ(static_cast<int>(p), 5);
  EXPECT_TRUE(parsePenalty("request_for_pickup", &p));
  EXPECT_EQ(static_cast<int>(p), 8);
  EXPECT_STREQ(penaltyName(Penalty::Manual), "manual");
}
