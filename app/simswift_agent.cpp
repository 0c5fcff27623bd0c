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
// `simswift-agent --help` lists its options (declared once, with CLI11, in
// declareOptions()); a bad command line exits with status 2, naming the option.
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
#include <tuple>
#include <utility>

#include "common/libagent/AgentConnection.hpp"
#include "common/libagent/SharedNames.hpp"
#include "agent/program/RobotProgram.hpp"
#include "agent/program/RobotSetup.hpp"
#include "agent/behaviour/BehaviourYaml.hpp"
#include "common/config/ConfigError.hpp"
#include "app/cli/CommandLine.hpp"

namespace {

namespace al = common::libagent;
namespace ap = agent::program;
namespace cli = simswift::cli;

void printSensors(const common::libagent::SensorValues& s, int64_t t_us) {
  std::printf("t %.2f s\n  joints (rad):", static_cast<double>(t_us) * 1e-6);
  for (int i = 0; i < al::kNumJoints; ++i) std::printf(" %s=%.3f", al::Joints::kNames[i], s.joints.angles[i]);
  std::printf("\n  sensors:");
  for (int i = 0; i < al::kNumSensors; ++i) std::printf(" %s=%.3f", al::Sensors::kNames[i], s.sensors[i]);
  std::printf("\n");
  std::fflush(stdout);
}

// The command line as the parser reads it.
struct Options {
  std::optional<int> team, player;
  std::optional<std::string> posture_name, behaviour, config;
  std::optional<uint64_t> seed;
  std::optional<std::tuple<double, double, double>> start;  // m, m, rad
  // joint, angle in rad (checked as a number by the parser; a pair of
  // strings because CLI11's pair<string, double> reading warns)
  std::optional<std::pair<std::string, std::string>> move;
  double move_at = 0, attach_timeout = 10;
  bool print = false, bare = false;
  std::optional<std::string> lola;  // the V6's socket
};

void declareOptions(CLI::App& app, Options& o) {
  app.footer("Exit codes: 0 the run ended; 1 the simulator is gone, the program failed or it could not\n"
             "attach; 2 bad command line or config file.");
  app.add_option("--team", o.team,
                 "SPL team number (0..255); with --player P the robot's\n"
                 "objects are /libagent-memory<N>, N = T x 11 + P")
      ->type_name("T")
      ->transform(cli::number(al::kMinTeamNumber, al::kMaxTeamNumber, true));
  app.add_option("--player", o.player, "player number (1..5)")
      ->type_name("P")
      ->transform(cli::number(al::kMinPlayer, al::kMaxPlayer, true));
  app.add_option("--config", o.config,
                 "the robot's setup (agent/program/RobotSetup.hpp): team,\n"
                 "player, seed, start, behaviour, actions, posture, script;\n"
                 "the flags override it")
      ->type_name("FILE");
  app.add_option("--behaviour", o.behaviour, agent::behaviour::behaviourNamesText())->type_name("NAME");
  app.add_option("--seed", o.seed, "the filters' random source (default 1)")->type_name("S")->transform(cli::seed());
  app.add_option("--start", o.start, "known start pose for localisation (m, m, rad; field frame)")
      ->type_name("X Y THETA")
      ->transform(cli::number());
  app.add_flag("--bare", o.bare, "use the robot build's bare names (/libagent-memory)");
  app.add_option("--posture", o.posture_name, "stand (default), crouch, limp or zero (no behaviour or actions)")
      ->type_name("NAME")
      ->transform(CLI::Validator(
          [](std::string& text) -> std::string {
            return ap::parsePosture(text) ? "" : "unknown posture '" + text + "'";
          },
          "", ""));
  app.add_option("--move", o.move, "move one joint (NAO name, e.g. HeadYaw) to ANGLE rad")
                              ->type_name("JOINT ANGLE")
                              ->transform(CLI::Validator(
                                  [](std::string& joint) -> std::string {
                                    return ap::jointIndex(joint) >= 0 ? "" : "unknown joint '" + joint + "'";
                                  },
                                  "", "")
                                              .application_index(0))
                              ->transform(cli::number().application_index(1));
  app.add_option("--at", o.move_at, "... at simulated time S s (default 0)")
      ->type_name("S")
      ->transform(cli::number());
  app.add_flag("--print", o.print,
               "print the sensors, game state and team packet counts\n"
               "every 100 ticks (1 s)");
  app.add_option("--attach-timeout", o.attach_timeout, "keep trying to attach for S wall-clock seconds (default 10)")
      ->type_name("S")
      ->transform(cli::number());
  app.add_option("--lola", o.lola, "a NAO V6: Motion over LoLA's socket")
      ->type_name("[SOCKET]")
      ->expected(0, 1)
      ->default_str(std::string(common::lola::kDefaultSocketPath));
}

// The setup: the config file, then the flags. An exit code if they are bad.
std::optional<int> readSetup(const CLI::App& app, const Options& o, ap::RobotSetup& setup) {
  try {
    if (o.config) setup = ap::readRobotSetup(*o.config);
    if (o.behaviour)
      setup.behaviour = agent::behaviour::behaviourFromText(*o.behaviour, "", "--behaviour", &setup.behaviour_yaml);
  } catch (const common::config::ConfigError& e) {
    std::fprintf(stderr, "simswift-agent: %s\n", e.what());
    return 2;
  }
  if (o.team) setup.team = *o.team;
  if (o.player) setup.player = *o.player;
  if (o.seed) setup.seed = *o.seed;
  if (o.start) {
    ap::RobotSetup::StartPose p;  // m, m, rad (as RobotSetup holds it)
    p.x = std::get<0>(*o.start);
    p.y = std::get<1>(*o.start);
    p.theta = std::get<2>(*o.start);
    setup.start = p;
  }
  if (o.posture_name) setup.posture = *ap::parsePosture(*o.posture_name);
  if (!o.config && !o.team) return cli::usageError(app, "--team is needed (or a --config file that names it)");
  if (!o.config && !o.player) return cli::usageError(app, "--player is needed (or a --config file that names it)");
  if (setup.team < al::kMinTeamNumber || setup.team > al::kMaxTeamNumber)
    return cli::usageError(app, "--team must be an SPL team number " + std::to_string(al::kMinTeamNumber) + ".." +
                                    std::to_string(al::kMaxTeamNumber));
  if (setup.player < al::kMinPlayer || setup.player > al::kMaxPlayer)
    return cli::usageError(app, "--player must be " + std::to_string(al::kMinPlayer) + ".." +
                                    std::to_string(al::kMaxPlayer));
  if (o.move) {
    ap::ScriptStep s;
    s.joint = ap::jointIndex(o.move->first);
    s.angle = static_cast<float>(*cli::parseNumber(o.move->second));
    s.t_s = o.move_at;
    setup.script.push_back(s);
  }
  return std::nullopt;
}

// --print: once a simulated second.
void printTick(ap::RobotProgram& program, const al::SensorValues& s, int64_t t_us) {
  if (t_us % 1000000 != 0) return;
  printSensors(s, t_us);
  const agent::blackboard::GameInfo g = program.board().game.read();
  const agent::blackboard::TeamInfo tm = program.board().team.read();
  std::printf("  game: known %d state %s penalised %d | team: received %lld malformed %lld\n", g.known ? 1 : 0,
              agent::blackboard::gameStateName(g.state), g.penalised ? 1 : 0,
              static_cast<long long>(tm.received), static_cast<long long>(tm.malformed));
  std::fflush(stdout);
}

// Runs the robot program on the attached robot until the simulator ends the
// run; the exit code.
int runAttached(al::AgentConnection conn, const ap::RobotSetup& setup, const Options& o) {
  std::fprintf(stderr, "simswift-agent: attached to %s\n", conn.name().c_str());
  // The game state and the team link come through the extension object
  // beside the block (filled by the simulator as for builtin robots).
  ap::ProgramConfig pc = ap::composeProgram(setup);
  pc.extensions = conn.extension();
  std::unique_ptr<ap::BodyConnection> body;
  if (o.lola) {
    // The V6: the joints over LoLA's socket; the block found above is not used.
    body = ap::lolaBody(common::lola::LolaConnection::connect(*o.lola, o.attach_timeout), std::move(conn));
    std::fprintf(stderr, "simswift-agent: connected to LoLA at %s\n", o.lola->c_str());
  } else {
    body = ap::libagentBody(std::move(conn));
  }
  ap::RobotProgram program(std::move(body), std::move(pc));
  if (o.print)
    program.setAfterTick([&program](const al::SensorValues& s, int64_t t_us) { printTick(program, s, t_us); });
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
}

// The simulator may not have created the robot yet: retry for a while
// (wall clock: attaching only).
int attachAndRun(const ap::RobotSetup& setup, const Options& o) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(o.attach_timeout);
  for (;;) {
    try {
      return runAttached(
          al::AgentConnection::attach(o.bare ? al::bareNames() : al::simulationNames(setup.team, setup.player)),
          setup, o);
    } catch (const common::lola::LolaError& e) {
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("The reference robot program in its own process: attaches to a simulated robot's\n"
               "shared memory (libagent's names) and runs the modules of a builtin robot program.",
               "simswift-agent");
  Options o;
  declareOptions(app, o);
  if (const std::optional<int> code = cli::parse(app, argc, argv)) return *code;
  agent::program::RobotSetup setup;
  if (const std::optional<int> code = readSetup(app, o, setup)) return *code;
  return attachAndRun(setup, o);
}
