// simswift: runs a scenario headless, as fast as it can (or paced with
// --realtime), and prints a one-line summary; and its other subcommands:
// experiment [merge] (app/experiment/Command.cpp), test
// (app/scenario_tests/TestCommand.cpp), clean, attach, view (app/view/ViewCommand.cpp). The command line is
// declared once, with CLI11 (app/cli): `simswift [SUBCOMMAND] --help` prints
// what the parser reads.
//
// Exit codes: 0 success, 1 run failure (watchdog, I/O), 2 bad command line
// (the message names the option) or bad input file (scenario, model, field:
// the message names file and line); experiment and test: also 130 interrupted.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/mman.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app/cli/CommandLine.hpp"
#include "common/clock/ClockPage.hpp"
#include "common/v4l2/DeviceBlock.hpp"
#include "common/libagent/SharedNames.hpp"
#include "app/experiment/BehaviourHooks.hpp"
#include "app/experiment/Command.hpp"
#include "app/scenario_tests/TestCommand.hpp"
#include "app/view/ViewCommand.hpp"
#include "sim/bridge/V4l2Devices.hpp"
#include "sim/lola/LolaServer.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/programs/JoinView.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/programs/ProgramProcess.hpp"
#include "sim/programs/ShimEnvironment.hpp"
#include "sim/runner/Bodies.hpp"
#include "sim/record/Recorder.hpp"
#include "sim/runner/RunStats.hpp"
#include "sim/runner/Runner.hpp"

namespace {

namespace al = common::libagent;
namespace cli = simswift::cli;

// --team T --player P: a robot by its SPL numbers (clean, attach).
struct RobotOptions {
  std::optional<int> team, player;
  CLI::Option* team_opt = nullptr;
  CLI::Option* player_opt = nullptr;

  // `what`: whose numbers ("of the robot").
  void declare(CLI::App& cmd, const std::string& what) {
    team_opt = cmd.add_option("--team", team, "SPL team number " + what + " (with --player)")
                   ->type_name("T")
                   ->transform(cli::number(al::kMinTeamNumber, al::kMaxTeamNumber, true));
    player_opt = cmd.add_option("--player", player, "player number " + what + " (with --team)")
                     ->type_name("P")
                     ->transform(cli::number(al::kMinPlayer, al::kMaxPlayer, true));
    team_opt->needs(player_opt);
    player_opt->needs(team_opt);
  }
};

// simswift run SCENARIO.yaml [options]
class RunCommand {
 public:
  explicit RunCommand(CLI::App& parent) {
    cmd_ = parent.add_subcommand("run", "run a scenario and print its summary");
    cmd_->footer(
        "Runs a scenario in lock-step with its robot programs and prints\n"
        "  sim S s | wall W s | Fx real time | falls N | blowups N | hash H\n"
        "then a line per robot: where it ended, its falls, up or down\n"
        "  tTpP: x X m  y Y m  theta A rad  falls N  up|down\n"
        "\n"
        "Exit codes: 0 success, 1 run failure (watchdog, I/O), 2 bad command line or bad\n"
        "scenario, model or field (the message names the file and line).");
    cmd_->add_option("SCENARIO", path_, "the scenario file (SCENARIO.yaml)")->type_name("")->required();
    declareRunOptions();
    declareOutputOptions();
  }
  RunCommand(const RunCommand&) = delete;
  RunCommand& operator=(const RunCommand&) = delete;

  bool chosen() const { return cmd_->parsed(); }
  int run();

 private:
  // How the scenario runs: pace, checks, overrides of the scenario's settings.
  void declareRunOptions() {
    cmd_->add_flag("--realtime", opt_.realtime,
                   "pace the run with the wall clock (default: as fast as possible);\n"
                   "external robot programs run free: not waited for, skipped\n"
                   "cycles counted, 50 in a row sit the robot down");
    cmd_->add_flag("--check", check_, "validate the scenario, its model and field; run nothing");
    cmd_->add_flag("--inline", inline_,
                   "run builtin robot programs' Motion and Perception steps on the\n"
                   "simulator's thread (faster; same hash; no named robot threads for gdb)");
    cmd_->add_option("--duration", duration_, "simulated seconds (overrides the scenario)")
        ->type_name("S")
        ->transform(cli::number(0.01, 1e6));
    cmd_->add_option("--seed", seed_, "noise seed (overrides the scenario)")->type_name("N")->transform(cli::seed());
    cmd_->add_flag("--no-noise", no_noise_, "exact sensors");
    cmd_->add_option("--watchdog", watchdog_,
                     "wall-clock seconds a robot thread may take to answer (default " +
                         simswift::runner::formatNumber("%g", simswift::runner::Scenario{}.watchdog_s) + ");\n"
                     "off, or a debugger attached, never ends the run (README: Debugging in gdb)")
        ->type_name("S|off")
        ->transform(CLI::Validator(
            [](std::string& text) -> std::string {
              if (text == "off") {
                text = "0";  // Scenario::watchdog_s: 0 = off
                return "";
              }
              return cli::number(1e-3, simswift::runner::kMaxWallClockS)(text);
            },
            "", ""));
    cmd_->add_option("--model", model_, "robot model (overrides the scenario's model:)")
        ->type_name("URDF")
        ->transform(cli::nonEmpty());
    cmd_->add_option("--field", field_, "field (overrides the scenario's field:)")
        ->type_name("YAML")
        ->transform(cli::nonEmpty());
    cmd_->add_option("--attach-timeout", attach_,
                     "wall-clock seconds to wait for external robots (default " +
                         simswift::runner::formatNumber("%g", simswift::runner::Scenario{}.attach_timeout_s) + ")")
        ->type_name("S")
        ->transform(cli::number(1e-3, simswift::runner::kMaxWallClockS));
    cmd_->add_option("--print-hash-every", opt_.print_hash_every,
                     "print the state hash every N ticks (10 ms each; 12 ms on a V6)")
        ->type_name("N")
        ->transform(cli::number(1, 1e12, true));
    cmd_->add_flag("--quiet", quiet_, "no progress lines");
  }

  // What the run writes besides its summary: camera frames, overview, FindBall views.
  void declareOutputOptions() {
    CLI::Option* dump = cmd_->add_option("--dump-frames", dump_dir_,
                                         "render both cameras of every robot at 30 Hz and write\n"
                                         "DIR/t<team>p<player>_<top|bottom>_<frame>.png")
                            ->type_name("DIR")
                            ->transform(cli::nonEmpty());
    cmd_->add_option("--every", every_, "with --dump-frames: keep every N-th camera frame (default 1)")
        ->type_name("N")
        ->transform(cli::number(1, 1e6, true))
        ->needs(dump);
    cmd_->add_option("--overview", overview_dir_, "whole-field overview PNGs in DIR (+ DIR/overview.mp4 with ffmpeg)")
        ->type_name("DIR")
        ->transform(cli::nonEmpty());
    std::vector<std::string> sizes;
    for (const auto& [name, size] : simswift::runner::cameraResolutions()) sizes.push_back(name);
    cmd_->add_option("--resolution", resolution_,
                     "both robot cameras' resolution: 640x480 (default) or 1280x960\n"
                     "(each its own: the scenario's camera: {resolution: {top: WxH, bottom: WxH}})")
        ->type_name("WxH")
        ->transform(cli::oneOf(sizes));
    CLI::Option* findball = cmd_->add_option("--findball-view", findball_dir_,
                                             "FindBall view PNGs of every behaving robot in DIR/<robot>/\n"
                                             "(+ DIR/<robot>.mp4 with ffmpeg)")
                                ->type_name("DIR")
                                ->transform(cli::nonEmpty());
    cmd_->add_option("--findball-view-rate", findball_rate_, "frames per simulated second (default 2)")
        ->type_name("HZ")
        ->transform(cli::number(1e-3, 100))
        ->needs(findball);
    CLI::Option* record = cmd_->add_option("--record", record_path_,
                                           "record the run as MCAP (docs/recording.md): poses, joints,\n"
                                           "sensors, events, team messages; `simswift view FILE.mcap` replays it")
                              ->type_name("FILE.mcap")
                              ->transform(cli::nonEmpty());
    cmd_->add_option("--record-rate", record_rate_,
                     "samples per simulated second of poses, joints and sensors (default " +
                         simswift::runner::formatNumber("%g", simswift::record::RecordOptions::kDefaultRateHz) +
                         "; at most one per tick)")
        ->type_name("HZ")
        ->transform(cli::number(0.1, 1000))
        ->needs(record);
  }

  std::optional<int> loadScenario(simswift::runner::Scenario& sc) const;
  void applyOverrides(simswift::runner::Scenario& sc) const;
  int check(const simswift::runner::Scenario& sc) const;
  int runScenario(const simswift::runner::Scenario& sc);

  CLI::App* cmd_ = nullptr;
  std::string path_;
  simswift::runner::RunOptions opt_;
  bool check_ = false;    // validate scenario, model and field; run nothing
  bool inline_ = false;   // builtin programs on the simulator's thread
  bool no_noise_ = false;
  bool quiet_ = false;
  std::optional<double> duration_, watchdog_, attach_;
  std::optional<uint64_t> seed_;
  std::optional<std::string> model_, field_, dump_dir_, overview_dir_, resolution_, findball_dir_;
  std::optional<int> every_;
  std::optional<double> findball_rate_;  // frames per simulated s
  std::optional<std::string> record_path_;  // --record FILE.mcap
  std::optional<double> record_rate_;       // Hz of simulated time
};

int RunCommand::run() {
  using namespace simswift::runner;
  if ((dump_dir_ || overview_dir_) && !Runner::camerasAvailable())
    return cli::usageError(*cmd_, std::string(dump_dir_ ? "--dump-frames" : "--overview") +
                                      ": this simswift was built without cameras (configure with "
                                      "-DSIMSWIFT_CAMERAS=ON and OSMesa, assimp and libpng installed)");
  if (quiet_) opt_.progress = false;

  Scenario sc;
  if (const std::optional<int> code = loadScenario(sc)) return *code;
  applyOverrides(sc);
  if (check_) return check(sc);
  // Progress lines only on runs long enough to wonder about.
  if (sc.duration < 10) opt_.progress = false;
  return runScenario(sc);
}

// The exit code if the scenario cannot be read.
std::optional<int> RunCommand::loadScenario(simswift::runner::Scenario& sc) const {
  try {
    sc = simswift::runner::Scenario::loadFile(path_);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simswift: %s\n", e.what());
    return 2;
  }
  return std::nullopt;
}

void RunCommand::applyOverrides(simswift::runner::Scenario& sc) const {
  if (duration_) sc.duration = *duration_;
  if (seed_) sc.seed = *seed_;
  if (no_noise_) sc.noise.on = false;
  if (watchdog_) sc.watchdog_s = *watchdog_;
  if (attach_) sc.attach_timeout_s = *attach_;
  // Command-line paths resolve against the working directory.
  auto absolute = [](const std::string& p) { return std::filesystem::absolute(p).string(); };
  if (model_) sc.model_path = absolute(*model_);
  if (field_) sc.field_path = absolute(*field_);
  if (dump_dir_) sc.camera.dump_dir = *dump_dir_;
  if (every_) sc.camera.dump_every = *every_;
  if (resolution_)  // both cameras (oneOf above checked the name)
    if (const auto size = simswift::runner::cameraResolution(*resolution_))
      sc.camera.resolution[0] = sc.camera.resolution[1] = *size;
  if (overview_dir_) {
    sc.camera.overview.enabled = true;
    sc.camera.overview.dir = *overview_dir_;
  }
}

// --check: what Runner::start() would refuse before the first tick, without
// starting robot programs (an external robot's program need not run).
int RunCommand::check(const simswift::runner::Scenario& sc) const {
  try {
    const simswift::RobotModel model = simswift::RobotModel::loadUrdf(sc.modelFile());
    const simswift::NaoBinding nao(model);  // every robot runs on libagent
    sc.checkAgainstField(simswift::FieldConfig::loadYaml(sc.fieldFile()));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simswift: %s\n", e.what());
    return 2;
  }
  std::printf("%s: ok (%zu robots, %g s)\n", path_.c_str(), sc.robots.size(), sc.duration);
  return 0;
}

int RunCommand::runScenario(const simswift::runner::Scenario& sc) {
  using namespace simswift::runner;
  try {
    Runner runner(sc);
    if (inline_) runner.programs().setThreading(simswift::programs::Threading::Inline);
    if (findball_dir_) {
      sim::views::FindBallRecorderConfig fc;
      fc.dir = *findball_dir_;
      if (findball_rate_) fc.rate_hz = *findball_rate_;
      runner.setFindBallView(fc);
    }
    std::unique_ptr<simswift::record::Recorder> recorder;
    if (record_path_) {
      simswift::record::RecordOptions ro;
      if (record_rate_) ro.rate_hz = *record_rate_;
      recorder = std::make_unique<simswift::record::Recorder>(*record_path_, ro);
      runner.addObserver(recorder.get());
    }
    try {
      const RunStats stats = runner.run(opt_);
      std::printf("%s\n%s", stats.summary().c_str(), stats.robotLines().c_str());
      for (const std::string& log : runner.programs().logs()) std::printf("  program log %s\n", log.c_str());
      if (recorder) {
        recorder->finish();
        std::printf("  recording %s (%llu messages; simswift view %s)\n", recorder->path().c_str(),
                    static_cast<unsigned long long>(recorder->messages()), recorder->path().c_str());
      }
      std::fflush(stdout);
    } catch (const WatchdogError& e) {
      // The silent robot thread cannot be joined; remove the named objects
      // and leave without waiting for it.
      std::fprintf(stderr, "simswift: %s\n", e.what());
      if (recorder) {
        recorder->event(simswift::record::LogLevel::Error, "watchdog", e.what());
        recorder->finish();
        std::fprintf(stderr, "simswift: recording %s\n", recorder->path().c_str());
      }
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

// simswift clean [--team T --player P]: removes the named objects a killed
// simulator left in /dev/shm (all robots, or that robot under every
// release's names) and names the pid of any simulator still running one.
class CleanCommand {
 public:
  explicit CleanCommand(CLI::App& parent) {
    cmd_ = parent.add_subcommand("clean", "remove objects a killed run left in /dev/shm");
    cmd_->footer(
        "Removes the shared memory, camera device blocks and LoLA sockets killed runs left\n"
        "(every robot's, or one robot's under every libagent release's names); a running\n"
        "simswift's are left alone and its pid named. Exit codes: 0 done, 2 bad command line.");
    robot_.declare(*cmd_, "of the robot to clean up (default: every robot)");
  }
  CleanCommand(const CleanCommand&) = delete;
  CleanCommand& operator=(const CleanCommand&) = delete;

  bool chosen() const { return cmd_->parsed(); }
  int run() const;

 private:
  CLI::App* cmd_ = nullptr;
  RobotOptions robot_;
};

int CleanCommand::run() const {
  namespace sb = simswift::bridge;
  std::vector<std::string> only;
  if (robot_.team)
    for (sb::Release rel : {sb::Release::R2017, sb::Release::R2018})
      only.push_back(sb::releaseNames(rel, *robot_.team, *robot_.player, false).memory);
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
  if (!robot_.team) {
    const std::vector<std::string> sockets =
        simswift::lola::removeStaleSockets({simswift::lola::kSharedSocketFolder}, "t");
    const std::vector<std::string> trials = simswift::lola::removeStaleSockets({"/dev/shm"}, "simswift-lola-p");
    std::printf("removed %zu LoLA socket(s) left by killed runs\n", sockets.size() + trials.size());
  } else {
    const std::string tag = common::libagent::robotTag(*robot_.team, *robot_.player);
    const auto sockets = simswift::lola::removeStaleSockets({simswift::lola::kSharedSocketFolder}, tag);
    std::printf("removed %zu LoLA socket(s) of %s left by killed runs\n", sockets.size(), tag.c_str());
  }
  // Camera device blocks (sim/bridge/V4l2Devices.hpp) no running simswift serves.
  const std::vector<std::string> blocks =
      sb::V4l2Devices::removeStale(robot_.team ? common::libagent::robotTag(*robot_.team, *robot_.player) : "");
  std::printf("removed %zu camera device block(s) left by killed runs\n", blocks.size());
  return 0;
}

// simswift attach (--team T --player P | --socket PATH) -- COMMAND...: runs
// COMMAND (execvp) for an external robot of a run that has started: in the
// robot's view the run holds (sim/programs/JoinView.hpp), or, where the
// machine gives none, in a mount namespace of its own where /tmp/robocup is
// the V6 robot's socket (docs/lola.md). main() hands over what follows the
// first `--` untouched; the parser never sees it.
class AttachCommand {
 public:
  explicit AttachCommand(CLI::App& parent) {
    cmd_ = parent.add_subcommand("attach", "run an unchanged robot program by hand, in its robot's view");
    cmd_->footer(
        "simswift attach (--team T --player P | --socket PATH) -- COMMAND...\n"
        "Runs COMMAND, an unchanged robot program (or gdb running it), by hand for a robot\n"
        "whose program is external. It waits (up to --wait s) for a run to serve that robot\n"
        "(its clock page; a V6's socket too, default /tmp/simswift-lola/t<T>p<P>).\n"
        "Where the machine gives namespaces, the run holds the view a launched program gets\n"
        "and COMMAND runs in it: its own processes, the robot's /tmp with /tmp/robocup its\n"
        "socket, /home/nao and files, wlan0 at 10.0.<T>.<P> with the GameController's packets\n"
        "and the team's network (docs/porting.md section 10); it ends with the run, as a\n"
        "launched program does. Elsewhere a V6's /tmp/robocup is the robot's socket, in a\n"
        "mount namespace of its own, following a new run of the same robot.\n"
        "Everything after -- is the command's, passed on as it is. COMMAND reads the robot's\n"
        "simulated time through libsimswift-shim.so (LD_PRELOAD; docs/shim.md), as a launched\n"
        "program does; a static binary is refused. When the run serves the robot's cameras\n"
        "(scenario key v4l2:, on by default in a build with cameras), COMMAND streams them\n"
        "as a launched program does (/dev/video-top and /dev/video-bottom on a V6,\n"
        "/dev/video0 and /dev/video1 on a V5, or the scenario's paths), in lock-step.\n"
        "COMMAND may be gdb running the program: gdb keeps the wall clock.\n"
        "\n"
        "Exit codes: COMMAND's (128 + N killed by signal N); 1 no run served the robot in time\n"
        "or COMMAND cannot start; 2 bad command line.");
    robot_.declare(*cmd_, "of the robot");
    CLI::Option* socket = cmd_->add_option("--socket", socket_, "the robot's LoLA socket (instead of --team, --player)")
                              ->type_name("PATH")
                              ->transform(cli::nonEmpty());
    socket->excludes(robot_.team_opt);
    socket->excludes(robot_.player_opt);
    cmd_->add_option("--clock", clock_,
                     "the robot's clock page (default /simswift-clock-t<T>p<P>, from --team and --player or the "
                     "socket's name)")
        ->type_name("NAME")
        ->transform(cli::nonEmpty());
    cmd_->add_option("--wait", wait_s_, "s to wait for a run to serve the socket (default " +
                                            simswift::runner::formatNumber("%g", wait_s_) + ")")
        ->transform(cli::number(0, 1e6));
    // Only for --help and to say where the command goes: main() takes it
    // from after `--`.
    cmd_->add_option("COMMAND", misplaced_, "the program and its arguments, after --")->type_name("");
  }
  AttachCommand(const AttachCommand&) = delete;
  AttachCommand& operator=(const AttachCommand&) = delete;

  bool chosen() const { return cmd_->parsed(); }
  int run(const std::vector<std::string>& command) const;

 private:
  CLI::App* cmd_ = nullptr;
  RobotOptions robot_;
  std::string socket_;
  std::string clock_;
  // s, wall clock: as long as a run waits for its hand-started program
  // (the scenario's attach_timeout default).
  double wait_s_ = simswift::runner::Scenario{}.attach_timeout_s;
  std::vector<std::string> misplaced_;  // a command given before `--`
};

namespace attach {
volatile sig_atomic_t g_forward = 0;  // a signal for the command (SIGTERM, SIGHUP)
void onSignal(int sig) { g_forward = sig; }

// The robot's socket as the command sees it differs from the one served at
// `socket` now (a new run of the robot): /tmp/robocup is bound to the new one.
bool follow(const std::string& socket) {
  struct stat served {}, seen {};
  if (!simswift::lola::socketServed(socket) || ::stat(socket.c_str(), &served) != 0) return false;
  if (::stat("/tmp/robocup", &seen) == 0 && seen.st_dev == served.st_dev && seen.st_ino == served.st_ino) return false;
  ::umount2("/tmp/robocup", MNT_DETACH);
  return ::mount(socket.c_str(), "/tmp/robocup", nullptr, MS_BIND, nullptr) == 0;
}

// Polls ready() every 20 ms until it holds (true) or `deadline` has passed
// (false). Wall clock: only how long attach waits for a run, never what the
// run does.
template <class Ready, class Deadline>
bool waitFor(Ready ready, Deadline deadline) {
  while (!ready()) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

}  // namespace attach

int AttachCommand::run(const std::vector<std::string>& command) const {
  if (!misplaced_.empty())
    return cli::usageError(*cmd_, "unknown argument '" + misplaced_[0] + "' (the command goes after --)");
  if (command.empty()) return cli::usageError(*cmd_, "no command after --");
  if (socket_.empty() && !robot_.team) return cli::usageError(*cmd_, "give --team and --player, or --socket");
  const std::string socket =
      socket_.empty() ? simswift::runner::defaultLolaSocket(*robot_.team, *robot_.player, false) : socket_;
  // The robot's clock page: named by its robot (common/clock/ClockPage.hpp).
  std::string tag;
  int team = 0, player = 0;
  if (robot_.team) tag = common::libagent::robotTag(*robot_.team, *robot_.player);
  else if (common::libagent::parseRobotTag(std::filesystem::path(socket).filename().string(), &team, &player))
    tag = common::libagent::robotTag(team, player);
  const std::string clock = !clock_.empty() ? clock_ : tag.empty() ? "" : common::clock::pageName(tag);
  if (clock.empty())
    return cli::usageError(*cmd_, "the robot's clock page cannot be told from --socket " + socket +
                                      ": give --clock NAME (the run's /simswift-clock-t<T>p<P>)");
  // The run's clock page set up by a live run (its flags, its view), and for
  // a V6 (the page says so, or --socket) the socket of a run that serves it,
  // never one a run left or one not made yet: waited for (bounded), as a
  // real client retries its connect. Wall clock: only how long to wait,
  // never what the run does.
  namespace cc = common::clock;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s_);
  std::optional<simswift::programs::RunPage> page;
  const auto isLola = [&] { return !socket_.empty() || (page && (page->flags & cc::kFlagLola)); };
  const auto served = [&] {
    page = simswift::programs::readRunPage(clock);
    return page && (!isLola() || simswift::lola::socketServed(socket));
  };
  const std::string robot = socket_.empty() ? "robot " + tag : socket;
  if (!served()) {
    std::fprintf(stderr, "simswift attach: waiting up to %g s for a run to serve %s\n", wait_s_, robot.c_str());
    if (!attach::waitFor(served, deadline)) {
      std::fprintf(stderr,
                   "simswift attach: no run served %s (its clock page %s%s) within %g s (start the run with "
                   "this robot, or give --wait more time)\n",
                   robot.c_str(), clock.c_str(), isLola() ? (", socket " + socket).c_str() : "", wait_s_);
      return 1;
    }
  }
  const bool lola = isLola();
  // The robot's cameras, when the run serves them (its clock page says so):
  // the block named by the robot, made before the page; waited for in what
  // is left of --wait all the same (its FIFOs held by the run).
  std::string v4l2_block;
  if (page->flags & cc::kFlagV4l2ByRobot) {
    if (tag.empty()) {
      std::fprintf(stderr,
                   "simswift attach: the run serves this robot's cameras, but its name cannot be told from --socket "
                   "%s: the command gets no cameras (give --team and --player)\n",
                   socket.c_str());
    } else {
      v4l2_block = common::v4l2::blockName(tag);
      if (!attach::waitFor([&] { return simswift::bridge::V4l2Devices::served(v4l2_block); }, deadline)) {
        std::fprintf(stderr,
                     "simswift attach: robot %s: the run serves its cameras, but their block %s was not there "
                     "within %g s\n",
                     tag.c_str(), v4l2_block.c_str(), wait_s_);
        return 1;
      }
    }
  }
  simswift::programs::Environment env;
  try {
    env = simswift::programs::shimLaunchEnvironment(tag.empty() ? clock : tag, command[0], {clock, v4l2_block}, {});
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "simswift attach: %s\n", e.what());
    return 1;
  }
  // The robot's view, when the run holds one (its page says so: an external
  // robot on a machine with namespaces): the command runs in it, as a
  // launched program would (sim/programs/JoinView.hpp). Else a V6's
  // /tmp/robocup alone, in a mount namespace of this process's own.
  const bool in_view = (page->flags & cc::kFlagView) != 0;
  std::vector<simswift::programs::MountOp> mounts;
  std::error_code cwd_error;
  const std::string cwd = std::filesystem::current_path(cwd_error).string();
  if (in_view) {
    env.emplace_back("SIMSWIFT_PID_NAMESPACE_OF_PROGRAM", "1");  // simswift's own client (Liveness.cpp)
    std::vector<std::string> named(command.begin(), command.end());
    named.push_back(cwd);
    for (char** e = environ; *e; ++e) named.emplace_back(*e);
    for (const auto& [k, v] : env) named.push_back(v);
    try {
      mounts = simswift::programs::joinedMounts(page->view_folder, lola ? socket : "", named);
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "simswift attach: robot %s's view: %s\n", tag.c_str(), e.what());
      return 1;
    }
    const std::string error = simswift::programs::enterViewNamespaces(page->view_pid);
    if (!error.empty()) {
      std::fprintf(stderr, "simswift attach: %s\n", error.c_str());
      return 1;
    }
  } else if (lola) {
    const std::string error = simswift::programs::ProgramProcess::enterPrivateRobocup(socket);
    if (!error.empty()) {
      std::fprintf(stderr, "simswift attach: %s\n", error.c_str());
      return 1;
    }
  }
  for (const auto& [k, v] : env) setenv(k.c_str(), v.c_str(), 1);
  std::vector<char*> argv;
  for (const std::string& a : command) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  // The command runs in this mount namespace; this process stays to keep
  // its /tmp/robocup on the robot's live socket (a new run of the robot
  // makes a new one), and ends with the command's status.
  int report[2];
  if (pipe2(report, O_CLOEXEC) != 0) return 1;
  const pid_t parent = getpid();
  const pid_t child = fork();
  if (child < 0) {
    std::fprintf(stderr, "simswift attach: fork: %s\n", std::strerror(errno));
    return 1;
  }
  if (child == 0) {
    prctl(PR_SET_PDEATHSIG, SIGTERM);  // attach killed: the command is told to end
    // In the view's PID namespace this process's parent has no pid (0); an
    // orphan's is the view's init (1) or the machine's.
    if (getppid() != (in_view ? 0 : parent)) _exit(127);
    if (in_view) {
      const char* what = "";
      if (const int e = simswift::programs::enterJoinedMounts(mounts, &what)) {
        std::fprintf(stderr, "simswift attach: cannot give the command robot %s's view: %s: %s\n", tag.c_str(), what,
                     std::strerror(e));
        _exit(127);
      }
      if (chdir(cwd.c_str()) != 0) {
        std::fprintf(stderr, "simswift attach: the folder %s is not in robot %s's view: %s\n", cwd.c_str(),
                     tag.c_str(), std::strerror(errno));
        _exit(127);
      }
    }
    execvp(argv[0], argv.data());
    const int e = errno;
    ssize_t w = write(report[1], &e, sizeof e);
    (void)w;
    _exit(127);
  }
  close(report[1]);
  int exec_error = 0;
  const bool failed = read(report[0], &exec_error, sizeof exec_error) == static_cast<ssize_t>(sizeof exec_error);
  close(report[0]);
  // The terminal's Ctrl-C and Ctrl-\ reach the command itself (same group);
  // a SIGTERM or SIGHUP sent to attach is passed on.
  signal(SIGINT, SIG_IGN);
  signal(SIGQUIT, SIG_IGN);
  struct sigaction sa {};
  sa.sa_handler = attach::onSignal;
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGHUP, &sa, nullptr);
  int status = 0;
  for (;;) {
    const pid_t r = waitpid(child, &status, WNOHANG);
    if (r == child) break;
    if (r < 0 && errno != EINTR) return 1;
    if (attach::g_forward) {
      kill(child, attach::g_forward);
      attach::g_forward = 0;
    }
    if (!failed && lola && !in_view && attach::follow(socket))
      std::fprintf(stderr, "simswift attach: a new run serves %s: /tmp/robocup follows it\n", socket.c_str());
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  if (failed) std::fprintf(stderr, "simswift attach: cannot start '%s': %s\n", argv[0], std::strerror(exec_error));
  const int code = failed ? 1 : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : WIFEXITED(status) ? WEXITSTATUS(status) : 1;
  if (in_view) {
    // Ended here: this process entered the view's PID namespace for its
    // children, and a sanitizer's exit-time leak check stops the world with a
    // child task that would be born there, unable to trace this process
    // ("LeakSanitizer does not work under ptrace"), failing the exit.
    std::fflush(nullptr);
    _exit(code);
  }
  return code;
}

// What CLI11 would only call "a subcommand is required": `help`, or an
// unknown first word. The exit code if main() is done.
std::optional<int> checkFirstWord(const CLI::App& app, int argc, char** argv) {
  if (argc < 2) return std::nullopt;
  const std::string first = argv[1];
  if (first == "help") {
    std::fputs(app.help().c_str(), stdout);
    return 0;
  }
  const bool known = !app.get_subcommands([&](const CLI::App* c) { return c->check_name(first); }).empty() ||
                     app.get_option_no_throw(first) != nullptr;
  if (!known)
    return cli::usageError(app, (first[0] == '-' ? "unknown option '" : "unknown command '") + first + "'");
  return std::nullopt;
}

// attach: what follows the first `--` is the command, handed over as it is.
// Returns how many arguments the parser reads.
int splitAttachCommand(int argc, char** argv, std::vector<std::string>& command) {
  if (argc < 2 || std::string(argv[1]) != "attach") return argc;
  const auto dashes = std::find(argv + 2, argv + argc, std::string("--"));
  if (dashes != argv + argc) command.assign(dashes + 1, argv + argc);
  return static_cast<int>(dashes - argv);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Runs NAO robot-soccer scenarios, experiments and scenario tests (docs/runner.md).", "simswift");
  app.footer(
      "`simswift SUBCOMMAND --help` lists its options.\n"
      "Exit codes: 0 success, 1 run failure (watchdog, I/O), 2 bad command line or bad input\n"
      "file (the message names the option, or the file and line); experiment and test: 130 interrupted.");
  app.set_version_flag("--version", std::string("simswift ") + SIMSWIFT_VERSION);
  app.require_subcommand(1);
  RunCommand run(app);
  simswift::experiment::ExperimentCommand experiment(app);
  simswift::scenario_tests::TestCommand test(app);
  CleanCommand clean(app);
  AttachCommand attach(app);
  simswift::view::ViewCommand view(app);

  if (const std::optional<int> code = checkFirstWord(app, argc, argv)) return *code;
  std::vector<std::string> command;
  const int parsed_argc = splitAttachCommand(argc, argv, command);
  if (const std::optional<int> code = cli::parse(app, parsed_argc, argv)) return *code;

  if (run.chosen()) return run.run();
  if (experiment.chosen()) return experiment.run(simswift::experiment::behaviourHooks());  // agent/behaviour's
  if (test.chosen()) return test.run();
  if (clean.chosen()) return clean.run();
  if (view.chosen()) return view.run();
  return attach.run(command);
}
