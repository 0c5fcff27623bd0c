// The robot program's Blackboard and modules: start-up refuses a module that
// reads an unprovided section; a scenario's actions reach Motion through the
// behaviour request at frame time; every frame runs the Perception modules.
#include <gtest/gtest.h>

#include <ctime>
#include <string>

#include "agent/libagent/SharedNames.hpp"
#include "agent/program/RobotProgram.hpp"

namespace al = agent::libagent;
namespace ap = agent::program;
namespace bb = agent::blackboard;

namespace {
// An in-process body side without a simulator: ticks and frames by hand.
struct Body {
  std::unique_ptr<al::AgentData> block{new al::AgentData()};
  std::unique_ptr<al::SimExtension> ext{new al::SimExtension()};
  sem_t tick;
  Body() {
    sem_init(&tick, 0, 0);
    sem_init(&ext->answered, 1, 0);
    sem_init(&ext->camera.frame_ready, 1, 0);
    sem_init(&ext->camera.perception_done, 1, 0);
    ext->magic = al::kExtensionMagic;
    ext->version = al::kExtensionVersion;
  }
  ~Body() {
    sem_destroy(&tick);
    sem_destroy(&ext->answered);
    sem_destroy(&ext->camera.frame_ready);
    sem_destroy(&ext->camera.perception_done);
  }
  al::AgentConnection connect() { return al::AgentConnection(block.get(), &tick, ext.get()); }
  static bool wait(sem_t* s) {
    timespec d{};
    clock_gettime(CLOCK_REALTIME, &d);
    d.tv_sec += 5;
    return sem_timedwait(s, &d) == 0;
  }
  // One tick: sensors' time, park the actuators, post, wait for the answer.
  bool step(int64_t t_us) {
    ext->slot_time_us[0] = t_us;
    al::storeIndex(block->actuators_latest, al::kActuatorsParked);
    sem_post(&tick);
    return wait(&ext->answered);
  }
  bool frame(int64_t t_us, int64_t index) {
    ext->camera.frame.sim_time_us = t_us;
    ext->camera.frame.frame_index = index;
    sem_post(&ext->camera.frame_ready);
    return wait(&ext->camera.perception_done);
  }
  void shutdown() {
    ext->shutdown = 1;
    ext->camera.shutdown = 1;
    sem_post(&tick);
    sem_post(&ext->camera.frame_ready);
  }
};
}  // namespace

TEST(RobotProgramModules, MotionWithoutABehaviourFailsStartUpNamingBoth) {
  Body body;
  ap::ProgramConfig cfg;  // the Motion module, but no behaviour and no actions
  ap::RobotProgram program(body.connect(), std::move(cfg));
  try {
    program.start();
    FAIL() << "start() accepted a module reading an unprovided section";
  } catch (const agent::framework::ModuleError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("'motion'"), std::string::npos) << m;
    EXPECT_NE(m.find("'motion_request'"), std::string::npos) << m;
  }
  EXPECT_EQ(body.ext->client_pid.load(), 0);  // nothing announced
}

TEST(RobotProgramModules, ActionsReachMotionThroughTheMotionRequestAtFrameTime) {
  Body body;
  ap::ProgramConfig cfg;
  cfg.team = 1;
  cfg.player = 3;
  agent::motion::ActionStep walk;
  walk.t = 0.05;
  walk.body.type = bb::ActionType::WALK;
  walk.body.forward = 200;
  cfg.actions = {walk};
  {
    ap::RobotProgram program(body.connect(), std::move(cfg));
    program.start();
    EXPECT_NE(program.schedule().describe().find(
                  "game state -> vision adapter -> localisation -> ball tracker -> team receive -> "
                  "behaviour (action script) -> team send"),
              std::string::npos)
        << program.schedule().describe();
    EXPECT_NE(program.schedule().describe().find("Motion: motion -> effector"), std::string::npos);
    // 10 ms ticks; a frame whenever floor(t * 30) advances (as the runner does).
    int64_t last_frame = -1;
    for (int k = 1; k <= 10; ++k) {
      const int64_t t_us = k * 10000;
      ASSERT_TRUE(body.step(t_us)) << "tick " << k;
      const int64_t f = t_us * 30 / 1000000;
      if (f > last_frame) {
        last_frame = f;
        ASSERT_TRUE(body.frame(t_us, f)) << "frame " << f;
        const bb::MotionRequest req = program.board().motion_request.read();
        // Frames at 0.04 s and before: still the script's initial STAND.
        EXPECT_EQ(req.body.type, t_us >= 50000 ? bb::ActionType::WALK : bb::ActionType::STAND) << t_us;
        EXPECT_EQ(program.board().vision.read().frame_index, f);
        EXPECT_DOUBLE_EQ(program.board().localisation.read().time, t_us * 1e-6);
        EXPECT_EQ(program.board().frame.read().sim_time_us, t_us);
      }
    }
    EXPECT_EQ(program.perceptionFrames(), 4);  // frames at 0.01, 0.04, 0.07 and 0.10 s
    EXPECT_EQ(program.board().motion.read().tick, 10);
    // Motion (ticks 0.08 s on) has taken the walk request.
    EXPECT_EQ(program.board().motion.read().request_sequence, program.board().motion_request.read().sequence);
    body.shutdown();
  }
}
