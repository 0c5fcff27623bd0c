// The top-level Behaviour: game states, bad inputs, its outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>

#include "agent/behaviour/Behaviour.hpp"
#include "agent/behaviour/BehaviourYaml.hpp"
#include "common/config/ConfigError.hpp"

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

// One table of kinds: names and kinds agree both ways, in the enum's order,
// and every list of names is read from it.
TEST(Behaviour, KindsTable) {
  ASSERT_EQ(kNumBehaviourKinds, 3);
  for (const BehaviourKindRow& r : kBehaviourKinds) {
    BehaviourKind k = r.kind == BehaviourKind::STRIKER ? BehaviourKind::FINDBALL_2016 : BehaviourKind::STRIKER;
    EXPECT_TRUE(parseBehaviourKind(r.name, &k)) << r.name;
    EXPECT_EQ(k, r.kind) << r.name;
    EXPECT_STREQ(behaviourKindName(r.kind), r.name);
  }
  EXPECT_STREQ(behaviourKindName(static_cast<BehaviourKind>(kNumBehaviourKinds)), "?");
  EXPECT_STREQ(behaviourKindName(static_cast<BehaviourKind>(-1)), "?");
  EXPECT_EQ(behaviourNames(), (std::vector<std::string>{"findball2016", "findball2017", "striker", "script"}));
  EXPECT_EQ(behaviourNamesText(), "findball2016, findball2017, striker or script");
  BehaviourKind k = BehaviourKind::STRIKER;
  EXPECT_FALSE(parseBehaviourKind(kScriptBehaviourName, &k));  // script is no kind
  EXPECT_EQ(k, BehaviourKind::STRIKER);
  // The reader's error lists the table's names.
  std::string error;
  try {
    behaviourFromText("findball2018", "", "x.yaml");
  } catch (const common::config::ConfigError& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("expected one of findball2016, findball2017, striker, script (got 'findball2018')"),
            std::string::npos)
      << error;
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
