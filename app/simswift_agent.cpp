// simswift-agent: the reference robot program in its own process. It
// attaches to a simulated robot's named shared memory by libagent's names
// (/libagent-memory<N>, N = team x 11 + player, or the bare ones) and runs
// the same modules as a scenario's `program: builtin` robot: Motion,
// Perception (the 30 Hz camera frame's observations), localisation, team
// comms, the game state and a behaviour or timed body actions, composed by
// agent/program/RobotSetup.hpp from its config file and flags. It uses only
// the libagent block and simswift's extension objects beside it, so it is
// also the template a team reads to attach its own program.
//
//   simswift-agent --team T --player P [--behaviour NAME] [--config FILE]
//                  [--seed S] [--start X Y THETA] [--posture NAME]
//                  [--move JOINT ANGLE [--at S]] [--bare] [--print] [--attach-timeout S]
//                  [--lola [SOCKET]]
//
// --lola: the robot is a NAO V6: Motion talks to its LoLA socket (default
// /tmp/robocup, what a launched program sees as its robot's: docs/lola.md)
// instead of libagent's block (agent/program/BodyConnection.hpp); the
// camera frames, game state and team link still come through simswift's
// extension object, found by the team and player as on a V5.
//
// simswift launches it with `program: {command: [simswift-agent, --config,
// "{config}"]}`: {config} is the robot's setup as a builtin program gets it,
// so both give the same state hash. It runs until the simulator ends the
// run; if the simulator is killed it notices within a second and exits with
// status 1 and a message.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <thread>

#include "agent/config/Seed.hpp"
#include "agent/libagent/AgentConnection.hpp"
#include "agent/libagent/SharedNames.hpp"
#include "agent/program/RobotProgram.hpp"
#include "agent/program/RobotSetup.hpp"
#include "agent/behaviour/BehaviourYaml.hpp"
#include "agent/config/ConfigError.hpp"

namespace {

const char* kUsage =
    "usage: simswift-agent [--team T --player P] [options]\n"
    "  --team T             SPL team number (0..255); with --player P the robot's\n"
    "                       objects are /libagent-memory<N>, N = T x 11 + P\n"
    "  --config FILE        the robot's setup (agent/program/RobotSetup.hpp): team,\n"
    "                       player, seed, start, behaviour, actions, posture, script;\n"
    "                       the flags below override it\n"
    "  --behaviour NAME     findball2016, findball2017, striker or script\n"
    "  --seed S             the filters' random source (default 1)\n"
    "  --start X Y THETA    known start pose for localisation (m, m, rad; field frame)\n"
    "  --bare               use the robot build's bare names (/libagent-memory)\n"
    "  --posture NAME       stand (default), crouch, limp or zero (no behaviour or actions)\n"
    "  --move JOINT ANGLE   move one joint (NAO name, e.g. HeadYaw) to ANGLE rad\n"
    "  --at S               ... at simulated time S s (default 0)\n"
    "  --print              print the sensors, game state and team packet counts\n"
    "                       every 100 ticks (1 s)\n"
    "  --attach-timeout S   keep trying to attach for S wall-clock seconds (default 10)\n"
    "  --lola [SOCKET]      a NAO V6: Motion over LoLA's socket (default /tmp/robocup)\n";

[[noreturn]] void usageError(const std::string& msg) {
  std::fprintf(stderr, "simswift-agent: %s\n\n%s", msg.c_str(), kUsage);
  std::exit(2);
}

double number(const char* s, const char* what) {
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  if (*end != '\0') usageError(std::string(what) + ": not a number: '" + s + "'");
  return v;
}

void printSensors(const agent::libagent::SensorValues& s, int64_t t_us) {
  namespace al = agent::libagent;
  std::printf("t %.2f s\n  joints (rad):", static_cast<double>(t_us) * 1e-6);
  for (int i = 0; i < al::kNumJoints; ++i) std::printf(" %s=%.3f", al::Joints::kNames[i], s.joints.angles[i]);
  std::printf("\n  sensors:");
  for (int i = 0; i < al::kNumSensors; ++i) std::printf(" %s=%.3f", al::Sensors::kNames[i], s.sensors[i]);
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  namespace al = agent::libagent;
  namespace ap = agent::program;
  std::optional<int> team, player;
  std::optional<ap::Posture> posture;
  std::optional<std::string> behaviour, config;
  std::optional<uint64_t> seed;
  std::optional<ap::RobotSetup::StartPose> start;
  std::string move_joint;
  double move_angle = 0, move_at = 0, attach_timeout = 10;
  bool print = false, bare = false;
  std::optional<std::string> lola;  // the V6's socket
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&](const char* what) -> const char* {
      if (i + 1 >= argc) usageError(std::string(what) + " needs a value");
      return argv[++i];
    };
    if (a == "--team") team = static_cast<int>(number(next("--team"), "--team"));
    else if (a == "--player") player = static_cast<int>(number(next("--player"), "--player"));
    else if (a == "--config") config = next("--config");
    else if (a == "--behaviour") behaviour = next("--behaviour");
    else if (a == "--seed") {
      const char* v = next("--seed");
      const std::optional<uint64_t> s = agent::config::parseSeed(v);
      if (!s) usageError(std::string("--seed must be ") + agent::config::kSeedRange + " (got '" + v + "')");
      seed = *s;
    } else if (a == "--start") {
      ap::RobotSetup::StartPose p;  // m, m, rad (as RobotSetup holds it)
      p.x = number(next("--start"), "--start X");
      p.y = number(next("--start"), "--start Y");
      p.theta = number(next("--start"), "--start THETA");
      start = p;
    } else if (a == "--posture") {
      const std::string p = next("--posture");
      auto parsed = ap::parsePosture(p);
      if (!parsed) usageError("--posture: unknown posture '" + p + "'");
      posture = *parsed;
    } else if (a == "--move") {
      move_joint = next("--move");
      move_angle = number(next("--move"), "--move ANGLE");
    } else if (a == "--at") move_at = number(next("--at"), "--at");
    else if (a == "--print") print = true;
    else if (a == "--bare") bare = true;
    else if (a == "--lola")
      lola = i + 1 < argc && argv[i + 1][0] != '-' ? std::string(argv[++i]) : std::string(agent::lola::kDefaultSocketPath);
    else if (a == "--attach-timeout") attach_timeout = number(next("--attach-timeout"), "--attach-timeout");
    else if (a == "--help" || a == "-h") {
      std::printf("%s", kUsage);
      return 0;
    } else usageError("unknown argument '" + a + "'");
  }

  // The setup: the config file, then the flags.
  ap::RobotSetup setup;
  try {
    if (config) setup = ap::readRobotSetup(*config);
    if (behaviour)
      setup.behaviour = agent::behaviour::behaviourFromText(*behaviour, "", "--behaviour", &setup.behaviour_yaml);
  } catch (const agent::config::ConfigError& e) {
    std::fprintf(stderr, "simswift-agent: %s\n", e.what());
    return 2;
  }
  if (team) setup.team = *team;
  if (player) setup.player = *player;
  if (seed) setup.seed = *seed;
  if (start) setup.start = start;
  if (posture) setup.posture = *posture;
  if (!config && !team) usageError("--team is needed (or a --config file that names it)");
  if (!config && !player) usageError("--player is needed (or a --config file that names it)");
  if (setup.team < al::kMinTeamNumber || setup.team > al::kMaxTeamNumber)
    usageError("--team must be an SPL team number " + std::to_string(al::kMinTeamNumber) + ".." +
               std::to_string(al::kMaxTeamNumber));
  if (setup.player < al::kMinPlayer || setup.player > al::kMaxPlayer)
    usageError("--player must be " + std::to_string(al::kMinPlayer) + ".." + std::to_string(al::kMaxPlayer));
  if (!move_joint.empty()) {
    ap::ScriptStep s;
    s.joint = ap::jointIndex(move_joint);
    if (s.joint < 0) usageError("--move: unknown joint '" + move_joint + "'");
    s.angle = static_cast<float>(move_angle);
    s.t_s = move_at;
    setup.script.push_back(s);
  }

  // The simulator may not have created the robot yet: retry for a while
  // (wall clock: attaching only).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(attach_timeout);
  for (;;) {
    try {
      al::AgentConnection conn =
          al::AgentConnection::attach(bare ? al::bareNames() : al::simulationNames(setup.team, setup.player));
      std::fprintf(stderr, "simswift-agent: attached to %s\n", conn.name().c_str());
      // The game state and the team link come through the extension object
      // beside the block (filled by the simulator as for builtin robots).
      ap::ProgramConfig pc = ap::composeProgram(setup);
      pc.extensions = conn.extension();
      std::unique_ptr<ap::BodyConnection> body;
      if (lola) {
        // The V6: the joints over LoLA's socket; the block found above is not used.
        body = ap::lolaBody(agent::lola::LolaConnection::connect(*lola, attach_timeout), std::move(conn));
        std::fprintf(stderr, "simswift-agent: connected to LoLA at %s\n", lola->c_str());
      } else {
        body = ap::libagentBody(std::move(conn));
      }
      ap::RobotProgram program(std::move(body), std::move(pc));
      if (print)
        program.setAfterTick([&program](const al::SensorValues& s, int64_t t_us) {
          if (t_us % 1000000 != 0) return;
          printSensors(s, t_us);
          const agent::blackboard::GameInfo g = program.board().game.read();
          const agent::blackboard::TeamInfo tm = program.board().team.read();
          std::printf("  game: known %d state %s penalised %d | team: received %lld malformed %lld\n", g.known ? 1 : 0,
                      agent::blackboard::gameStateName(g.state), g.penalised ? 1 : 0,
                      static_cast<long long>(tm.received), static_cast<long long>(tm.malformed));
          std::fflush(stdout);
        });
      program.start();
      program.join();
      if (program.simulatorGone()) {
        std::fprintf(stderr, "simswift-agent: the simulator is gone (killed?) after %lld ticks: exiting\n",
                     static_cast<long long>(program.motionTicks()));
        return 1;
      }
      std::fprintf(stderr, "simswift-agent: run ended after %lld ticks\n",
                   static_cast<long long>(program.motionTicks()));
      return program.error().empty() ? 0 : 1;
    } catch (const agent::lola::LolaError& e) {
      std::fprintf(stderr, "simswift-agent: %s\n", e.what());
      return 1;
    } catch (const al::AgentError& e) {
      if (std::chrono::steady_clock::now() > deadline) {
        std::fprintf(stderr, "simswift-agent: %s\n", e.what());
        return 1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
}
