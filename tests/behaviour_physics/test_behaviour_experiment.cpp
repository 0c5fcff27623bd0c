// The experiment's robots run agent/behaviour (app/experiment/BehaviourHooks):
// overrides are checked before any trial, naming the behaviour's file and line;
// a trial's scenario carries the behaviour.
#include <gtest/gtest.h>

#include "app/experiment/BehaviourHooks.hpp"
#include "app/experiment/Experiment.hpp"

using namespace simswift::experiment;

namespace {
std::string experiment(const std::string& config) {
  return "name: t\nseed: 1\ntime_limit: 10\ntrials_per_position: 1\nballs:\n  - {position: 1, x: 1.0, y: 0.0}\n"
         "setups:\n  - name: a\n    config: " + config + "\n    behaviour: findball2017\n    robots:\n"
         "      - {team: 19, player: 2, x: -1.0, y: 0.0, theta: 0.0}\n";
}
}  // namespace

TEST(BehaviourExperiment, OverridesCheckedBeforeTrials) {
  const Experiment good = Experiment::parse(experiment("{strategy: {distributed: off}}"), "exp.yaml");
  EXPECT_NO_THROW(checkBehaviours(good, behaviourHooks()));
  simswift::runner::Scenario sc;
  sc.robots.resize(1);
  TrialSpec t;
  t.setup = 0;
  RobotBehaviours().configure(good, t, sc);
  ASSERT_TRUE(sc.robots[0].setup.behaviour);
  EXPECT_EQ(sc.robots[0].setup.behaviour->kind, agent::behaviour::BehaviourKind::FINDBALL_2017);
  EXPECT_FALSE(sc.robots[0].setup.behaviour->strategy.distributed);

  const Experiment bad = Experiment::parse(experiment("{strategy: {distributd: off}}"), "exp.yaml");
  try {
    checkBehaviours(bad, behaviourHooks());
    ADD_FAILURE() << "unknown override accepted";
  } catch (const simswift::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("exp.yaml:10"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("distributd"), std::string::npos) << e.what();
  }
}
