// The top-level Behaviour: game states, bad inputs, its outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>

#include "agent/behaviour/Behaviour.hpp"

using namespace agent::behaviour;
using agent::blackboard::ActionType;

namespace {
BehaviourInputs playing(double t) {
  BehaviourInputs in;
  in.time = t;
  in.self.pose = {-3250, 3000, -kPi / 2};
  return in;
}
}  // namespace

TEST(Behaviour, StandsOutsidePlayingAndCountsRequests) {
  Behaviour b(BehaviourConfig{});
  BehaviourInputs in = playing(0);
  in.game.state = GameState::READY;
  auto out = b.tick(in);
  EXPECT_EQ(out.request.body.type, ActionType::STAND);
  EXPECT_EQ(out.request.sequence, 1);
  in.game.state = GameState::PLAYING;
  in.time = 0.1;
  out = b.tick(in);
  EXPECT_EQ(out.request.sequence, 2);
  EXPECT_EQ(out.request.body.type, ActionType::WALK);  // off to segment 1's centre
  ASSERT_TRUE(out.payload);
  EXPECT_EQ(out.payload->segment, 0);
  EXPECT_EQ(out.payload->player, in.player);
  // The payload survives the packet.
  const auto back = SearchPayload::fromBytes(out.payload->toBytes());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->segment, 0);
}

TEST(Behaviour, NonFinitePoseStandsAndKeepsTheDistributionValid) {
  Behaviour b(BehaviourConfig{});
  BehaviourInputs in = playing(0);
  b.tick(in);
  in.time = 0.1;
  in.self.pose.x = std::numeric_limits<double>::quiet_NaN();
  in.ball.seen_now = true;
  in.ball.field = {std::numeric_limits<double>::infinity(), 0};
  const auto out = b.tick(in);
  EXPECT_EQ(out.request.body.type, ActionType::STAND);
  const auto& p = b.findBall()->distribution.probabilities();
  for (double v : p) EXPECT_TRUE(std::isfinite(v));
  EXPECT_NEAR(std::accumulate(p.begin(), p.end(), 0.0), 1.0, 1e-12);
}

TEST(Behaviour, KindsFromScenarioNames) {
  BehaviourKind k = BehaviourKind::STRIKER;
  EXPECT_TRUE(parseBehaviourKind("findball2016", &k));
  EXPECT_EQ(k, BehaviourKind::FINDBALL_2016);
  EXPECT_TRUE(parseBehaviourKind("findball2017", &k));
  EXPECT_EQ(k, BehaviourKind::FINDBALL_2017);
  EXPECT_FALSE(parseBehaviourKind("findball2018", &k));
  EXPECT_EQ(k, BehaviourKind::FINDBALL_2017);
  BehaviourConfig c;
  c.kind = BehaviourKind::FINDBALL_2016;
  Behaviour b(c);
  EXPECT_EQ(b.findBall(), nullptr);
  EXPECT_FALSE(b.tick(playing(0)).payload);  // the 2016 behaviour sends no search data
}
