// A test's behaviour in a builtin robot's production schedule
// (Programs::setBehaviour with agent/behaviour/RequestedBehaviour.hpp), its
// Motion module's configuration (Programs::setMotionConfig) and the command
// the simulator latched (Runner::lastCommand): what the Motion physics
// tests, bench_motion and the tuning tools are built on.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "agent/behaviour/RequestedBehaviour.hpp"
#include "agent/program/StandardModules.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"

namespace ab = agent::behaviour;
namespace ap = agent::program;
namespace bb = agent::blackboard;
using simswift::runner::Runner;
using simswift::runner::RunnerError;
using simswift::runner::Scenario;

namespace {

Scenario standingRobot() {
  return Scenario::parse("duration: 5\nrobots:\n  - {team: 0, player: 1, x: -1.0, y: 0.0, posture: stand}\n",
                         "test.yaml");
}

void requestWalk(ab::MotionRequestMailbox& box, float forward) {
  box.set([&](bb::MotionRequest& r) {
    r.body.type = bb::ActionType::WALK;
    r.body.forward = forward;
    ++r.sequence;
  });
}

// The standing robot, inline, started with a RequestedBehaviour whose
// mailbox the test holds.
struct RequestedRobot {
  Runner runner{standingRobot()};
  std::shared_ptr<ab::MotionRequestMailbox> box;
  RequestedRobot() {
    runner.programs().setThreading(ap::Threading::Inline);
    auto b = std::make_unique<ab::RequestedBehaviour>();
    box = b->mailbox();
    runner.programs().setBehaviour(0, std::move(b));
    runner.start();
  }
};

struct NoMotion : agent::framework::MotionGenerator {
  void tick(const common::libagent::SensorValues&, int64_t, common::libagent::JointValues&) override {}
};

}  // namespace

// The behaviour takes the scenario's posture's place in the Perception
// thread; Motion is the standard Motion module, not the posture generator.
TEST(RunnerBehaviour, RunsInTheBehaviourSlotWithTheStandardActionMotion) {
  Runner r(standingRobot());
  r.programs().setThreading(ap::Threading::Inline);
  r.programs().setBehaviour(0, std::make_unique<ab::RequestedBehaviour>());
  r.start();
  const auto& schedule = r.programs().program(0)->schedule();
  const std::string order = schedule.describe();
  EXPECT_NE(order.find("behaviour (requested)"), std::string::npos) << order;
  EXPECT_NE(dynamic_cast<ap::MotionThreadModule*>(schedule.find("motion")), nullptr) << order;
  EXPECT_EQ(schedule.find("motion (generator)"), nullptr) << order;
  bool in_perception = false;
  for (const auto& m : schedule.modules(agent::framework::ThreadId::Perception))
    in_perception = in_perception || std::string(m->name()) == "behaviour (requested)";
  EXPECT_TRUE(in_perception) << order;
}

// A request set between ticks is on the Blackboard after the next camera
// frame (the end of a tick, after Motion ran: tick stage 10) and followed
// by the Motion module on the tick after it: 2-5 ticks, the frames being
// 3 or 4 ticks apart (30 per second, 100 ticks per second).
TEST(RunnerBehaviour, ARequestReachesMotionThroughTheBlackboardWithinFiveTicks) {
  RequestedRobot q;
  Runner& r = q.runner;
  const std::shared_ptr<ab::MotionRequestMailbox>& box = q.box;
  for (int i = 0; i < 50; ++i) r.tick();
  int seen_min = 99, seen_max = 0;
  for (int k = 0; k < 12; ++k) {  // twelve requests at the phases of the camera frames
    requestWalk(*box, 100.0f + k);
    const int64_t want = box->latest().sequence;
    int ticks = 0;
    while (r.programs().program(0)->board().motion.read().request_sequence != want && ticks < 10) {
      r.tick();
      ++ticks;
    }
    EXPECT_GE(ticks, 2) << "request " << k;
    EXPECT_LE(ticks, 5) << "request " << k;
    seen_min = std::min(seen_min, ticks);
    seen_max = std::max(seen_max, ticks);
    EXPECT_EQ(r.programs().program(0)->board().motion_request.read().body.forward, 100.0f + k);
    for (int i = 0; i < 7 + k; ++i) r.tick();
  }
  EXPECT_EQ(seen_min, 2);  // every phase was met
  EXPECT_EQ(seen_max, 5);
}

// The command latched each tick is the one the program's Motion module
// computed that tick (its Blackboard's actuator request).
TEST(RunnerBehaviour, LastCommandIsWhatTheProgramSent) {
  RequestedRobot q;
  Runner& r = q.runner;
  const std::shared_ptr<ab::MotionRequestMailbox>& box = q.box;
  requestWalk(*box, 200.0f);
  for (int i = 0; i < 150; ++i) {
    r.tick();
    const bb::ActuatorRequest sent = r.programs().program(0)->board().actuators.read();
    const common::libagent::ActuatorCommand& got = r.lastCommand(0);
    for (int j = 0; j < common::libagent::kNumJoints; ++j) {
      ASSERT_EQ(got.joints.angles[j], sent.joints.angles[j]) << "tick " << i << " joint " << j;
      ASSERT_EQ(got.joints.stiffnesses[j], sent.joints.stiffnesses[j]) << "tick " << i << " joint " << j;
    }
  }
  EXPECT_EQ(r.programs().program(0)->board().motion.read().active, bb::ActionType::WALK);
}

// The test's MotionConfig is the Motion module's.
TEST(RunnerBehaviour, MotionConfigReachesTheActionMotion) {
  agent::motion::MotionConfig cfg;
  cfg.max_getup_attempts = 2;
  cfg.kick.ankle_roll_margin = -1.0;
  Runner r(standingRobot());
  r.programs().setThreading(ap::Threading::Inline);
  r.programs().setBehaviour(0, std::make_unique<ab::RequestedBehaviour>());
  r.programs().setMotionConfig(0, cfg);
  r.start();
  auto* m = dynamic_cast<ap::MotionThreadModule*>(r.programs().program(0)->schedule().find("motion"));
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->motion().config().max_getup_attempts, 2);
  EXPECT_EQ(m->motion().config().kick.ankle_roll_margin, -1.0);
}

// A behaviour and a motion generator together would leave the behaviour's
// request unread: start() says so.
TEST(RunnerBehaviour, BehaviourWithAMotionGeneratorIsAnError) {
  Runner r(standingRobot());
  r.programs().setThreading(ap::Threading::Inline);
  r.programs().setBehaviour(0, std::make_unique<ab::RequestedBehaviour>());
  r.programs().setMotionGenerator(0, std::make_unique<NoMotion>());
  try {
    r.start();
    FAIL() << "no error";
  } catch (const RunnerError& e) {
    EXPECT_NE(std::string(e.what()).find("setBehaviour and setMotionGenerator"), std::string::npos) << e.what();
  }
}
