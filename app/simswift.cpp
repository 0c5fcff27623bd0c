// simswift: runs a scenario headless, as fast as it can (or paced with
// --realtime), and prints a one-line summary.
//
//   simswift experiment FILE.yaml [--out DIR] [--jobs N] [--shard K/N]
//   simswift experiment merge DIR... --out DIR      (sim/experiment/Command.cpp)
//   simswift test FILE.yaml [--short] [--baseline DIR] [--junit FILE]   (sim/scenario_tests/TestCommand.cpp)
//   simswift clean [--team T --player P]
//   simswift attach (--team T --player P | --socket PATH) -- COMMAND...
//   simswift run SCENARIO.yaml [--realtime] [--duration S] [--seed N]
//                [--no-noise] [--watchdog S|off] [--print-hash-every N]
//                [--model URDF] [--field YAML]
//                [--dump-frames DIR [--every N]] [--overview DIR] [--resolution WxH]
//                [--findball-view DIR [--findball-view-rate HZ]]
//
// Exit codes: 0 success, 1 run failure (watchdog, I/O), 2 bad command line
// or bad input file (scenario, model, field: the message names file and line).
#include <algorithm>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>

#include <unistd.h>

#include "sim/experiment/BehaviourHooks.hpp"
#include "sim/experiment/Command.hpp"
#include "sim/scenario_tests/TestCommand.hpp"
#include "agent/config/Seed.hpp"
#include "sim/lola/LolaServer.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/programs/ProgramProcess.hpp"
#include "sim/runner/Bodies.hpp"
#include "sim/runner/Runner.hpp"

namespace {

// The defaults it prints are the scenario's own (sim/runner/Scenario.hpp).
const std::string kUsage =
    "usage: simswift run SCENARIO.yaml [options]\n"
    "       simswift experiment FILE.yaml [--out DIR] [--jobs N] [--shard K/N]   (see experiment --help)\n"
    "       simswift experiment merge DIR... --out DIR\n"
    "       simswift test FILE.yaml [--short] [--baseline DIR] [--junit FILE] [--jobs N]   (see test --help)\n"
    "       simswift clean [--team T --player P]   remove objects a killed run left in /dev/shm\n"
    "       simswift attach (--team T --player P | --socket PATH) -- COMMAND...\n"
    "                      run an unchanged V6 (LoLA) program by hand: its /tmp/robocup is that\n"
    "                      robot's socket (default /tmp/simswift-lola/t<T>p<P>), in a mount namespace of its own\n"
    "       simswift --version | --help\n"
    "\n"
    "Runs a scenario in lock-step with its robot programs and prints\n"
    "  sim S s | wall W s | Fx real time | falls N | blowups N | hash H\n"
    "then a line per robot: where it ended, its falls, up or down\n"
    "  tTpP: x X m  y Y m  theta A rad  falls N  up|down\n"
    "\n"
    "options:\n"
    "  --realtime             pace the run with the wall clock (default: as fast as possible);\n"
    "                         external robot programs run free: not waited for, skipped\n"
    "                         cycles counted, 50 in a row sit the robot down\n"
    "  --check                validate the scenario, its model and field; run nothing\n"
    "  --inline               run builtin robot programs' Motion and Perception steps on the\n"
    "                         simulator's thread (faster; same hash; no named robot threads for gdb)\n"
    "  --duration S           simulated seconds (overrides the scenario)\n"
    "  --seed N               noise seed (overrides the scenario)\n"
    "  --no-noise             exact sensors\n"
    "  --watchdog S|off       wall-clock seconds a robot thread may take to answer (default " +
    simswift::runner::formatNumber("%g", simswift::runner::Scenario{}.watchdog_s) + ");\n"
    "                         off, or a debugger attached, never ends the run (README: Debugging in gdb)\n"
    "  --model URDF           robot model (overrides the scenario's model:)\n"
    "  --field YAML           field (overrides the scenario's field:)\n"
    "  --attach-timeout S     wall-clock seconds to wait for external robots (default " +
    simswift::runner::formatNumber("%g", simswift::runner::Scenario{}.attach_timeout_s) + ")\n"
    "  --print-hash-every N   print the state hash every N ticks (10 ms each; 12 ms on a V6)\n"
    "  --quiet                no progress lines\n"
    "  --dump-frames DIR      render both cameras of every robot at 30 Hz and write\n"
    "                         DIR/t<team>p<player>_<top|bottom>_<frame>.png\n"
    "  --every N              with --dump-frames: keep every N-th camera frame (default 1)\n"
    "  --overview DIR         whole-field overview PNGs in DIR (+ DIR/overview.mp4 with ffmpeg)\n"
    "  --resolution WxH       robot camera resolution: 640x480 (default) or 1280x960\n"
    "  --findball-view DIR    FindBall view PNGs of every behaving robot in DIR/<robot>/\n"
    "                         (+ DIR/<robot>.mp4 with ffmpeg)\n"
    "  --findball-view-rate HZ  frames per simulated second (default 2)\n";

[[noreturn]] void usageError(const std::string& msg) {
  std::fprintf(stderr, "simswift: %s\n\n%s", msg.c_str(), kUsage.c_str());
  std::exit(2);
}

double numberArg(int& i, int argc, char** argv, const char* name, double lo, double hi) {
  if (i + 1 >= argc) usageError(std::string(name) + " needs a value");
  const std::string v = argv[++i];
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !(d >= lo) || !(d <= hi))
    usageError(std::string(name) + ": bad value '" + v + "' (must be in [" + std::to_string(lo) + ", " +
               std::to_string(hi) + "])");
  return d;
}

// --seed: any 64-bit seed (agent/config/Seed.hpp), digits only.
uint64_t seedArg(int& i, int argc, char** argv) {
  if (i + 1 >= argc) usageError("--seed needs a value");
  const std::string v = argv[++i];
  const std::optional<uint64_t> n = agent::config::parseSeed(v);
  if (!n) usageError(std::string("--seed: must be ") + agent::config::kSeedRange + " (got '" + v + "')");
  return *n;
}

}  // namespace

// simswift clean [--team T --player P]: removes the named objects a killed
// simulator left in /dev/shm (all robots, or that robot under every
// release's names) and names the pid of any simulator still running one.
int cleanMain(int argc, char** argv) {
  std::optional<int> team, player;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--team") team = static_cast<int>(numberArg(i, argc, argv, "--team", agent::libagent::kMinTeamNumber,
                                                      agent::libagent::kMaxTeamNumber));
    else if (a == "--player") player = static_cast<int>(numberArg(i, argc, argv, "--player", agent::libagent::kMinPlayer,
                                                                agent::libagent::kMaxPlayer));
    else usageError("clean: unknown argument '" + a + "'");
  }
  if (team.has_value() != player.has_value()) usageError("clean: give both --team and --player, or neither");
  namespace sb = simswift::bridge;
  std::vector<std::string> only;
  if (team)
    for (sb::Release rel : {sb::Release::R2017, sb::Release::R2018})
      only.push_back(sb::releaseNames(rel, *team, *player, false).memory);
  const std::vector<std::string> removed = sb::removeStaleObjects({}, only);
  int live = 0;
  for (const sb::LiveRobot& r : sb::liveRobots()) {
    if (!only.empty() && std::find(only.begin(), only.end(), r.memory) == only.end()) continue;
    std::printf("%s: in use by a running simswift (pid %d): left alone\n", r.memory.c_str(), r.pid);
    ++live;
  }
  std::printf("removed %zu robot(s) left by killed runs; %d in use\n", removed.size(), live);
  // V6 robots' LoLA sockets (sim/runner/Bodies.hpp): a scenario's in
  // /tmp/simswift-lola, an experiment trial's in /dev/shm.
  if (!team) {
    const std::vector<std::string> sockets =
        simswift::lola::removeStaleSockets({"/tmp/simswift-lola"}, "t");
    const std::vector<std::string> trials = simswift::lola::removeStaleSockets({"/dev/shm"}, "simswift-lola-p");
    std::printf("removed %zu LoLA socket(s) left by killed runs\n", sockets.size() + trials.size());
  } else {
    const std::string tag = agent::libagent::robotTag(*team, *player);
    const auto sockets = simswift::lola::removeStaleSockets({"/tmp/simswift-lola"}, tag);
    std::printf("removed %zu LoLA socket(s) of %s left by killed runs\n", sockets.size(), tag.c_str());
  }
  return 0;
}

// simswift attach (--team T --player P | --socket PATH) -- COMMAND...: runs
// COMMAND (execvp) in a mount namespace of its own where /tmp/robocup is the
// LoLA robot's socket of a run that has started (docs/lola.md).
int attachMain(int argc, char** argv) {
  std::optional<int> team, player;
  std::string socket;
  int i = 2;
  for (; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--") break;
    if (a == "--team") team = static_cast<int>(numberArg(i, argc, argv, "--team", agent::libagent::kMinTeamNumber,
                                                      agent::libagent::kMaxTeamNumber));
    else if (a == "--player") player = static_cast<int>(numberArg(i, argc, argv, "--player", agent::libagent::kMinPlayer,
                                                                agent::libagent::kMaxPlayer));
    else if (a == "--socket" && i + 1 < argc) socket = argv[++i];
    else usageError("attach: unknown argument '" + a + "' (the command goes after --)");
  }
  if (i + 1 >= argc) usageError("attach: no command after --");
  if (socket.empty() && !(team && player)) usageError("attach: give --team and --player, or --socket");
  if (!socket.empty() && (team || player)) usageError("attach: give --team and --player, or --socket, not both");
  if (socket.empty()) socket = simswift::runner::defaultLolaSocket(*team, *player, false);
  const std::string error = simswift::programs::ProgramProcess::enterPrivateRobocup(socket);
  if (!error.empty()) {
    std::fprintf(stderr, "simswift attach: %s (start the run first: the robot's socket exists while it runs)\n",
                 error.c_str());
    return 1;
  }
  execvp(argv[i + 1], argv + i + 1);
  std::fprintf(stderr, "simswift attach: cannot start '%s': %s\n", argv[i + 1], std::strerror(errno));
  return 1;
}

int main(int argc, char** argv) {
  using namespace simswift::runner;
  if (argc < 2) usageError("missing command");
  const std::string cmd = argv[1];
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    std::printf("%s", kUsage.c_str());
    return 0;
  }
  if (cmd == "--version") {
    std::printf("simswift %s\n", SIMSWIFT_VERSION);
    return 0;
  }
  if (cmd == "experiment")  // the behaviours of agent/behaviour in the trials
    return simswift::experiment::experimentMain(argc - 1, argv + 1, simswift::experiment::behaviourHooks());
  if (cmd == "test") return simswift::scenario_tests::testMain(argc - 1, argv + 1);
  if (cmd == "clean") return cleanMain(argc, argv);
  if (cmd == "attach") return attachMain(argc, argv);
  if (cmd != "run") usageError("unknown command '" + cmd + "'");

  std::string path;
  RunOptions opt;
  std::optional<double> duration, watchdog, attach;
  std::optional<uint64_t> seed;
  bool no_noise = false;
  bool check = false;  // validate scenario, model and field; run nothing
  bool inline_programs = false;  // --inline: builtin programs on the simulator's thread
  std::optional<std::string> dump_dir, overview_dir, resolution, model, field;
  std::optional<int> every;
  std::optional<std::string> findball_dir;
  std::optional<double> findball_rate;
  auto stringArg = [&](int& i, const char* name) {
    if (i + 1 >= argc) usageError(std::string(name) + " needs a value");
    return std::string(argv[++i]);
  };
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--realtime") opt.realtime = true;
    else if (a == "--check") check = true;
    else if (a == "--inline") inline_programs = true;
    else if (a == "--duration") duration = numberArg(i, argc, argv, "--duration", 0.01, 1e6);
    else if (a == "--seed") seed = seedArg(i, argc, argv);
    else if (a == "--no-noise") no_noise = true;
    else if (a == "--watchdog") {
      if (i + 1 < argc && std::string(argv[i + 1]) == "off") {
        ++i;
        watchdog = 0.0;  // off
      } else {
        watchdog = numberArg(i, argc, argv, "--watchdog", 1e-3, kMaxWallClockS);
      }
    } else if (a == "--attach-timeout") attach = numberArg(i, argc, argv, "--attach-timeout", 1e-3, kMaxWallClockS);
    else if (a == "--model") model = stringArg(i, "--model");
    else if (a == "--field") field = stringArg(i, "--field");
    else if (a == "--print-hash-every")
      opt.print_hash_every = static_cast<int64_t>(numberArg(i, argc, argv, "--print-hash-every", 1, 1e12));
    else if (a == "--quiet") opt.progress = false;
    else if (a == "--dump-frames") dump_dir = stringArg(i, "--dump-frames");
    else if (a == "--overview") overview_dir = stringArg(i, "--overview");
    else if (a == "--findball-view") findball_dir = stringArg(i, "--findball-view");
    else if (a == "--findball-view-rate") {
      findball_rate = numberArg(i, argc, argv, "--findball-view-rate", 1e-3, 100);  // frames per simulated s
    }
    else if (a == "--every") {
      const double n = numberArg(i, argc, argv, "--every", 1, 1e6);
      if (n != static_cast<int>(n)) usageError("--every: must be a whole number of frames");
      every = static_cast<int>(n);
    } else if (a == "--resolution") {
      resolution = stringArg(i, "--resolution");
      if (*resolution != "640x480" && *resolution != "1280x960")
        usageError("--resolution: must be 640x480 or 1280x960 (got '" + *resolution + "')");
    }
    else if (a == "--help" || a == "-h") {
      std::printf("%s", kUsage.c_str());
      return 0;
    } else if (!a.empty() && a[0] == '-') usageError("unknown option '" + a + "'");
    else if (path.empty()) path = a;
    else usageError("more than one scenario given");
  }
  if (path.empty()) usageError("missing SCENARIO.yaml");
  if (every && !dump_dir) usageError("--every needs --dump-frames DIR");
  if (findball_rate && !findball_dir) usageError("--findball-view-rate needs --findball-view DIR");
  if ((dump_dir || overview_dir) && !Runner::camerasAvailable())
    usageError(std::string(dump_dir ? "--dump-frames" : "--overview") +
               ": this simswift was built without cameras (configure with -DSIMSWIFT_CAMERAS=ON and "
               "OSMesa, assimp and libpng installed)");

  Scenario sc;
  try {
    sc = Scenario::loadFile(path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simswift: %s\n", e.what());
    return 2;
  }
  if (duration) sc.duration = *duration;
  if (seed) sc.seed = *seed;
  if (no_noise) sc.noise.on = false;
  if (watchdog) sc.watchdog_s = *watchdog;
  if (attach) sc.attach_timeout_s = *attach;
  // Command-line paths resolve against the working directory.
  auto absolute = [](const std::string& p) { return std::filesystem::absolute(p).string(); };
  if (model) sc.model_path = absolute(*model);
  if (field) sc.field_path = absolute(*field);
  if (dump_dir) sc.camera.dump_dir = *dump_dir;
  if (every) sc.camera.dump_every = *every;
  if (resolution) {
    sc.camera.width = *resolution == "640x480" ? 640 : 1280;
    sc.camera.height = *resolution == "640x480" ? 480 : 960;
  }
  if (overview_dir) {
    sc.camera.overview.enabled = true;
    sc.camera.overview.dir = *overview_dir;
  }
  if (check) {
    // What Runner::start() would refuse before the first tick, without
    // starting robot programs (an external robot's program need not run).
    try {
      const simswift::RobotModel model = simswift::RobotModel::loadUrdf(sc.modelFile());
      const simswift::NaoBinding nao(model);  // every robot runs on libagent
      sc.checkAgainstField(simswift::FieldConfig::loadYaml(sc.fieldFile()));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "simswift: %s\n", e.what());
      return 2;
    }
    std::printf("%s: ok (%zu robots, %g s)\n", path.c_str(), sc.robots.size(), sc.duration);
    return 0;
  }
  // Progress lines only on runs long enough to wonder about.
  if (sc.duration < 10) opt.progress = false;

  try {
    Runner runner(sc);
    if (inline_programs) runner.programs().setThreading(agent::program::Threading::Inline);
    if (findball_dir) {
      sim::views::FindBallRecorderConfig fc;
      fc.dir = *findball_dir;
      if (findball_rate) fc.rate_hz = *findball_rate;
      runner.setFindBallView(fc);
    }
    try {
      const RunStats stats = runner.run(opt);
      std::printf("%s\n%s", stats.summary().c_str(), stats.robotLines().c_str());
      for (const std::string& log : runner.programs().logs()) std::printf("  program log %s\n", log.c_str());
      std::fflush(stdout);
    } catch (const WatchdogError& e) {
      // The silent robot thread cannot be joined; remove the named objects
      // and leave without waiting for it.
      std::fprintf(stderr, "simswift: %s\n", e.what());
      std::fflush(stdout);
      simswift::bridge::cleanup::removeAll();
      _exit(1);
    }
  } catch (const simswift::ConfigError& e) {
    std::fprintf(stderr, "simswift: %s\n", e.what());
    return 2;
  } catch (const simswift::ModelError& e) {
    std::fprintf(stderr, "simswift: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simswift: %s\n", e.what());
    return 1;
  }
  return 0;
}
