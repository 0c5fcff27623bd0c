// The robot program's Blackboard and modules: start-up refuses a module that
// reads an unprovided section; a scenario's actions reach Motion through the
// behaviour request at frame time; every frame runs the Perception modules;
// the game-state and team devices reach modules only through sections.
#include <gtest/gtest.h>

#include <ctime>
#include <string>

#include "agent/comms/SplMessage.hpp"
#include "common/libagent/SharedNames.hpp"
#include "agent/program/RobotProgram.hpp"

namespace al = common::libagent;
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

// The extension devices reach the modules only through sections: the program
// copies the game-state block into game_controller and the arrived packets
// into team_inbox before the Perception modules, and puts team send's
// team_outbox on the team link after them.
TEST(RobotProgramModules, TheDevicesReachTheModulesThroughSections) {
  Body body;
  al::GameStateBlock& g = body.ext->game;
  g.magic = al::kGameStateMagic;
  g.updates = 1;
  g.state = static_cast<uint8_t>(al::GameStateValue::Playing);
  g.teams[0].team_number = 1;
  g.teams[1].team_number = 2;
  g.teams[0].players[3 - 1].penalty = 5;  // any penalty: player 3 is penalised
  g.teams[0].players[3 - 1].secs_till_unpenalised = 20;
  agent::comms::SplMessage mate;
  mate.team = 1;
  mate.player = 2;
  mate.pose_x = 1500;
  const std::vector<uint8_t> bytes = agent::comms::serialise(mate);
  ASSERT_TRUE(body.ext->team.inbox.push(bytes.data(), bytes.size(), 5000, 2));

  ap::ProgramConfig cfg;
  cfg.team = 1;
  cfg.player = 3;
  cfg.extensions = body.ext.get();
  agent::motion::ActionStep stand;
  stand.body.type = bb::ActionType::STAND;
  cfg.actions = {stand};
  ap::RobotProgram program(body.connect(), std::move(cfg));
  program.start();
  ASSERT_TRUE(body.step(10000));
  ASSERT_TRUE(body.frame(10000, 0));

  const bb::GameControllerData gc = program.board().game_controller.read();
  EXPECT_TRUE(gc.present);
  EXPECT_EQ(gc.block.teams[0].players[2].secs_till_unpenalised, 20);
  const bb::GameInfo game = program.board().game.read();
  EXPECT_TRUE(game.known);
  EXPECT_EQ(game.state, bb::GameStateId::PLAYING);
  EXPECT_TRUE(game.penalised);
  const bb::TeamInbox inbox = program.board().team_inbox.read();
  EXPECT_TRUE(inbox.connected);
  ASSERT_EQ(inbox.packets.size(), 1u);
  EXPECT_EQ(inbox.packets[0].bytes, bytes);
  EXPECT_EQ(body.ext->team.inbox.size(), 0u);  // drained by the program, not by a module
  const bb::TeamInfo team = program.board().team.read();
  EXPECT_TRUE(team.mates[2].valid);
  EXPECT_FLOAT_EQ(static_cast<float>(team.mates[2].x), 1500.0f);
  // Our first message (the sender is due at once) went out through the link.
  ASSERT_EQ(program.board().team_outbox.read().packets.size(), 1u);
  EXPECT_EQ(body.ext->team.outbox.size(), 1u);
  al::TeamPacket sent{};
  ASSERT_TRUE(body.ext->team.outbox.pop(sent));
  const agent::comms::ParseResult parsed = agent::comms::parse(sent.bytes, sent.size);
  ASSERT_TRUE(parsed.ok());
  EXPECT_EQ(parsed.message.player, 3);
  body.shutdown();
}
