// Scenario `behaviour:` (agent/behaviour/BehaviourYaml): kinds, typed overrides,
// errors naming file, line and field; the module in the Perception order;
// the SearchPayload reaching teammates through the simulated network.
#include <gtest/gtest.h>

#include "harness/FindBallHarness.hpp"
#include "agent/behaviour/BehaviourYaml.hpp"
#include "tests/support/ConfigErrors.hpp"

using simswift::ConfigError;
using simswift::runner::Runner;
using simswift::runner::Scenario;
namespace ab = agent::behaviour;

namespace {
std::string robot(const std::string& extra) {
  return "robots:\n  - {team: 19, player: 2, x: -3, y: 3, " + extra + "}\n";
}
std::string errorOf(const std::string& text) {
  return simswift::testing::configError([&] { Scenario::parse(text, "b.yaml"); });
}
}  // namespace

TEST(BehaviourScenario, KindsAndDefault) {
  EXPECT_FALSE(Scenario::parse(robot("posture: stand"), "b.yaml").robots[0].setup.behaviour);
  EXPECT_FALSE(Scenario::parse(robot("behaviour: script"), "b.yaml").robots[0].setup.behaviour);
  const auto k = [](const std::string& name) {
    return Scenario::parse(robot("behaviour: " + name), "b.yaml").robots[0].setup.behaviour->kind;
  };
  EXPECT_EQ(k("findball2016"), ab::BehaviourKind::FINDBALL_2016);
  EXPECT_EQ(k("findball2017"), ab::BehaviourKind::FINDBALL_2017);
  EXPECT_EQ(k("striker"), ab::BehaviourKind::STRIKER);
}

TEST(BehaviourScenario, OverridesAreTyped) {
  const Scenario s = Scenario::parse(
      "robots:\n  - team: 19\n    player: 2\n    behaviour:\n      kind: findball2016\n"
      "      grid: {columns: 4, rows: 2}\n      strategy: {distributed: off, min_travel_time: 2}\n"
      "      search: {spin_at_point: no, points_2016: [{x: 0, y: 0}, {x: 1000, y: -500}]}\n"
      "      skills: {scan_speed: 1.5, kick_target: [4500, 500]}\n",
      "b.yaml");
  const ab::BehaviourConfig& c = *s.robots[0].setup.behaviour;
  EXPECT_EQ(c.kind, ab::BehaviourKind::FINDBALL_2016);
  EXPECT_EQ(c.grid.columns, 4);
  EXPECT_EQ(c.grid.rows, 2);
  EXPECT_FALSE(c.strategy.distributed);
  EXPECT_DOUBLE_EQ(c.strategy.min_travel_time, 2.0);
  EXPECT_FALSE(c.search.spin_at_point);
  EXPECT_TRUE(c.search.scan_at_point);  // untouched default
  ASSERT_EQ(c.search.points_2016.size(), 2u);
  EXPECT_DOUBLE_EQ(c.search.points_2016[1].y, -500);
  EXPECT_DOUBLE_EQ(c.skills.scan_speed, 1.5);
  EXPECT_DOUBLE_EQ(c.skills.kick_target.y, 500);
  EXPECT_DOUBLE_EQ(c.distribution.entropy_rate, ab::DistributionConfig{}.entropy_rate);
}

TEST(BehaviourScenario, ErrorsNameFileLineAndField) {
  EXPECT_NE(errorOf(robot("behaviour: findball2018")).find("b.yaml:2"), std::string::npos);
  EXPECT_NE(errorOf(robot("behaviour: findball2018")).find("behaviour"), std::string::npos);
  const std::string unknown = errorOf(robot("behaviour: {kind: findball2017, strategy: {distributd: off}}"));
  EXPECT_NE(unknown.find("b.yaml:2"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("distributd"), std::string::npos) << unknown;
  const std::string range = errorOf(robot("behaviour: {kind: striker, skills: {scan_speed: 20}}"));
  EXPECT_NE(range.find("scan_speed"), std::string::npos) << range;
  const std::string steer = errorOf(robot("behaviour: {kind: striker, skills: {pass_max_steer: 1.2}}"));
  EXPECT_NE(steer.find("b.yaml:2"), std::string::npos) << steer;
  EXPECT_NE(steer.find("pass_max_steer"), std::string::npos) << steer;
  EXPECT_NE(steer.find("translate_max_heading_error"), std::string::npos) << steer;
  const std::string section = errorOf(robot("behaviour: {kind: striker, tactics: {}}"));
  EXPECT_NE(section.find("tactics"), std::string::npos) << section;
  const std::string mixed = errorOf(robot("behaviour: findball2017, actions: [{t: 1, action: walk, forward: 100}]"));
  EXPECT_NE(mixed.find("actions"), std::string::npos) << mixed;
  const std::string ext = errorOf(robot("program: external, behaviour: striker"));
  EXPECT_NE(ext.find("behaviour"), std::string::npos) << ext;
}

// The module runs after team receive and before team send; teammates' packets
// carry the SearchPayload, decoded into each other's findball section.
TEST(BehaviourScenario, ModuleOrderAndPayloadBetweenTeammates) {
  Runner r(Scenario::parse(findball_harness::scenario(2, "findball2017", 0, 331, 3), "two.yaml"));
  r.start();
  const std::string order = r.programs().program(0)->schedule().describe();
  const size_t recv = order.find("team receive"), beh = order.find("behaviour"), send = order.find("team send");
  ASSERT_NE(beh, std::string::npos) << order;
  EXPECT_LT(recv, beh) << order;
  EXPECT_LT(beh, send) << order;
  while (r.ticks() < 300) r.tick();
  for (int i = 0; i < 2; ++i) {
    const agent::blackboard::FindBallInfo fb = r.programs().program(i)->board().findball.read();
    EXPECT_TRUE(fb.active);
    EXPECT_EQ(fb.team.size(), 9u);
    EXPECT_FALSE(fb.payload.empty());
    ASSERT_EQ(fb.teammates.size(), 1u) << i;
    EXPECT_EQ(fb.teammates[0].player, i == 0 ? 3 : 2);
    EXPECT_TRUE(fb.teammates[0].has_target) << "the teammate's packet names its search point";
    // The teammate's decoded segment is the one it is heading to.
    const agent::blackboard::FindBallInfo other = r.programs().program(1 - i)->board().findball.read();
    EXPECT_EQ(fb.teammates[0].segment, other.segment);
  }
  EXPECT_EQ(r.programs().program(0)->board().team.read().malformed, 0);
}

TEST(BehaviourScenario, ShippedFindBallScenariosLoad) {
  for (const char* f : {"findball_three_2017.yaml", "findball_three_2016.yaml", "findball_search_long.yaml"}) {
    const Scenario s = Scenario::loadFile(std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/" + f);
    ASSERT_GE(s.robots.size(), 3u) << f;
    for (const auto& r : s.robots) EXPECT_TRUE(r.setup.behaviour) << f;
  }
}

TEST(BehaviourScenario, FromKindAndOverrideText) {
  const auto c = agent::behaviour::behaviourFromText("findball2016", "{search: {spin_at_point: off}}", "exp.yaml");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->kind, ab::BehaviourKind::FINDBALL_2016);
  EXPECT_FALSE(c->search.spin_at_point);
  EXPECT_EQ(agent::behaviour::behaviourFromText("findball2017", "", "exp.yaml")->kind, ab::BehaviourKind::FINDBALL_2017);
  EXPECT_FALSE(agent::behaviour::behaviourFromText("script", "", "exp.yaml"));
  try {
    agent::behaviour::behaviourFromText("striker", "{skills: {bogus: 1}}", "exp.yaml");
    ADD_FAILURE() << "unknown key accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("bogus"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("exp.yaml"), std::string::npos) << e.what();
  }
}

// Behaving robots talk to each other and decide on what they hear: the same
// seed still gives the same state (lock-step, seeded noise, no wall clock).
TEST(BehaviourScenario, SameSeedSameStateWithBehavingTeammates) {
  auto hash = [] {
    Runner r(Scenario::parse(findball_harness::scenario(3, "findball2017", 1, 341, 6), "det.yaml"));
    r.start();
    while (r.ticks() < 600) r.tick();
    return r.world().stateHash();
  };
  const uint64_t a = hash();
  EXPECT_EQ(a, hash());
}
