#include "sim/programs/Programs.hpp"
#include "sim/programs/RobotNetwork.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include "common/libagent/SharedNames.hpp"
#include "common/lola/Protocol.hpp"
#include "agent/program/RobotSetup.hpp"
#include "sim/bridge/BodyHost.hpp"
#include "sim/programs/Errors.hpp"
#include "sim/programs/ExternalProgram.hpp"
#include "sim/programs/MountNamespace.hpp"
#include "sim/programs/ShimEnvironment.hpp"

namespace simswift::programs {

namespace al = common::libagent;
namespace ap = agent::program;

Programs::Programs(int num_robots) : robots_(static_cast<size_t>(num_robots)) {}

// Drivers go before anything they point into (the Runner's hosts outlive them).
Programs::~Programs() = default;

// Robot `robot`'s entry for an override given before the start.
Programs::Robot& Programs::overrideSlot(int robot, const char* what) {
  if (built_) throw RunnerError(std::string(what) + ": the runner has already started");
  if (robot < 0 || robot >= size()) throw RunnerError(std::string(what) + ": no robot " + std::to_string(robot));
  return robots_[robot];
}

void Programs::setMotionGenerator(int robot, std::unique_ptr<agent::framework::MotionGenerator> motion) {
  overrideSlot(robot, "setMotionGenerator").motion_override = std::move(motion);
}

void Programs::setBehaviour(int robot, std::unique_ptr<agent::framework::Module> behaviour) {
  overrideSlot(robot, "setBehaviour").behaviour_override = std::move(behaviour);
}

void Programs::setMotionConfig(int robot, const agent::motion::MotionConfig& config) {
  overrideSlot(robot, "setMotionConfig").motion_config = config;
}

void Programs::setPerceptionStep(int robot, std::unique_ptr<agent::framework::PerceptionStep> perception) {
  overrideSlot(robot, "setPerceptionStep").perception_override = std::move(perception);
}

void Programs::setStepHook(int robot, std::function<void(agent::framework::ThreadId)> hook) {
  overrideSlot(robot, "setStepHook").step_hook = std::move(hook);
}

void Programs::setController(int robot, RawController controller) {
  Robot& r = overrideSlot(robot, "setController");
  r.controller = std::move(controller);
  r.libagent_controller = nullptr;
}

void Programs::setLibagentController(int robot, RawLibagentController controller) {
  Robot& r = overrideSlot(robot, "setLibagentController");
  r.libagent_controller = std::move(controller);
  r.controller = nullptr;
}

void Programs::setThreading(ap::Threading threading) {
  if (built_) throw RunnerError("setThreading: the runner has already started");
  threading_ = threading;
}

void Programs::build(const ProgramRun& run, const std::vector<ProgramEntry>& robots) {
  if (built_) return;
  built_ = true;
  // A launched LoLA program this machine cannot give its view is refused
  // before any program starts.
  for (const ProgramEntry& e : robots)
    if (e.kind != ProgramKind::Builtin && e.launch.launched()) lolaView(e);
  for (const ProgramEntry& e : robots) {
    Robot& r = robots_[e.slot.index];
    if (e.kind == ProgramKind::Builtin) {
      r.driver = makeBuiltin(e, r);
      // Before the first Motion step: the program fills the extras each step.
      if (r.libagent_io) program(e.slot.index)->setLibagentIO(r.libagent_io);
    } else if (e.launch.launched()) {
      r.driver = makeLaunched(run, e);
    } else {
      r.driver = makeExternal(run, e);
    }
  }
}

// The robot program: the standard modules composed from the robot's setup
// (agent/program/RobotSetup.hpp: the same for a launched simswift-agent),
// Motion replaced by a test's generator or the API's controller if one was
// set, the Motion module configured by a test's MotionConfig if one was set.
std::unique_ptr<ProgramDriver> Programs::makeBuiltin(const ProgramEntry& e, Robot& r) {
  const RobotSlot& slot = e.slot;
  if (r.behaviour_override && r.motion_override)
    throw RunnerError("robot " + std::to_string(slot.index) +
                      ": setBehaviour and setMotionGenerator both given (the generator would leave the "
                      "behaviour's motion request unread)");
  std::unique_ptr<agent::framework::MotionGenerator> motion = std::move(r.motion_override);
  const bool api = r.controller || r.libagent_controller;
  if (r.controller) motion = ApiController::motionStep(std::move(r.controller));
  if (r.libagent_controller) {
    r.libagent_io = std::make_shared<LibagentExtras>();
    motion = ApiController::motionStep(std::move(r.libagent_controller), r.libagent_io);
  }
  ap::ProgramConfig pc = ap::composeProgram(e.setup, std::move(motion),
                                            r.motion_config ? *r.motion_config : agent::motion::MotionConfig());
  if (r.behaviour_override) {
    // A test's behaviour in the behaviour slot: it replaces the scenario's
    // behaviour, actions or held posture, and the standard Motion module
    // follows its requests.
    pc.behaviour = std::move(r.behaviour_override);
    pc.actions.clear();
    pc.motion_generator.reset();
  }
  pc.perception_step = std::move(r.perception_override);
  pc.step_hook = std::move(r.step_hook);
  // The game state and team link reach the program's modules. A test's
  // PerceptionStep that talks to the extension objects itself (through
  // Runner::extensions(i)) keeps them to itself: two readers would split the inbox.
  if (!pc.perception_step) pc.extensions = slot.host->extension();
  if (api) return std::make_unique<ApiController>(slot, std::move(pc));
  if (threading_ == ap::Threading::Inline) return std::make_unique<InlineProgram>(slot, std::move(pc));
  return std::make_unique<ThreadedProgram>(slot, std::move(pc));
}

// A launched LoLA program sees its robot's socket at /tmp/robocup, in a
// mount namespace of its own (ProgramProcess). Not needed when the robot's
// socket is the machine's /tmp/robocup itself (names: bare). Where the
// machine gives no namespace, a program that takes its socket's path
// ({socket} in its command or environment) is given the real path instead;
// an unchanged one cannot run (docs/lola.md): ProgramError.
Programs::LolaView Programs::lolaView(const ProgramEntry& e) {
  const RobotSlot& slot = e.slot;
  LolaView view;
  if (slot.host->interface() != bridge::BodyInterface::Lola) return view;
  const std::string socket = slot.host->endpoint();
  if (socket == common::lola::kDefaultSocketPath) return view;
  const NamespaceSupport ns = mountNamespaceSupport();
  if (ns.available) {
    view.robocup = socket;
  } else if (e.launch.names("socket")) {
    view.socket_placeholder = socket;
  } else {
    throw ProgramError("robot " + slot.tag + ": this machine gives its program no mount namespace of its own (" +
                           ns.why + "), so an unchanged LoLA program cannot see its robot's socket at " +
                           "/tmp/robocup: put {socket} in its command (it becomes " + socket +
                           ") or give the robot names: bare (its socket is then /tmp/robocup itself)",
                       slot.tag + ": program could not be started");
  }
  return view;
}

// A robot program's clock page (common/clock/ClockPage.hpp), named by its
// robot (`simswift attach` finds it so), at the bodies' cycle.
std::unique_ptr<ClockPage> Programs::clockPage(const ProgramRun& run, const ProgramEntry& e,
                                               const ClockPage::View& view) {
  try {
    // An external robot's cameras are in the block named by the robot: its
    // page says so, for `simswift attach` (a launched program is handed its
    // block in its environment), and so does its body.
    const bool by_robot = !e.v4l2_block.empty() && !e.launch.launched();
    const bool lola = e.slot.host->interface() == bridge::BodyInterface::Lola;
    const uint32_t flags = (by_robot ? common::clock::kFlagV4l2ByRobot : 0u) | (lola ? common::clock::kFlagLola : 0u);
    return std::make_unique<ClockPage>(common::clock::pageName(e.slot.tag), run.tick_us * 1000, run.clock_epoch_ns,
                                       flags, view);
  } catch (const std::runtime_error& err) {
    throw ProgramError("robot " + e.slot.tag + ": " + err.what(), e.slot.tag + ": program could not be started");
  }
}

// What a launched program sees (ProgramView.hpp), where the machine gives
// namespaces: its robot's socket at /tmp/robocup (a bare LoLA robot's is the
// machine's /tmp/robocup itself, bound at the same place), its folder of the
// run (<program_logs>/<tag>.view), the machine's /tmp paths its launch
// names, the default files and the scenario's.
ProgramView Programs::programView(const ProgramEntry& e, const std::filesystem::path& logs, const std::string& robocup,
                                  const std::vector<std::string>& argv, const std::string& cwd,
                                  const std::vector<std::pair<std::string, std::string>>& env,
                                  const std::string& config) {
  ProgramView view;
  view.isolate = mountNamespaceSupport().available;
  if (!view.isolate && e.launch.network == LaunchSpec::Network::On)
    throw ProgramError("robot " + e.slot.tag + ": network: on, but this machine gives its program no namespaces (" +
                           mountNamespaceSupport().why + "); give network: off",
                       e.slot.tag + ": no network namespace");
  if (!view.isolate) return view;
  view.robocup_socket = robocup;
  if (robocup.empty() && e.slot.host->interface() == bridge::BodyInterface::Lola)
    view.robocup_socket = e.slot.host->endpoint();  // names: bare: /tmp/robocup itself
  view.folder = std::filesystem::absolute(logs / (e.slot.tag + ".view")).lexically_normal().string();
  std::vector<std::string> named(argv.begin(), argv.end());
  named.push_back(std::filesystem::absolute(cwd).string());
  named.push_back(std::filesystem::absolute(config).string());
  named.push_back(view.folder);
  for (const auto& kv : env) named.push_back(kv.second);
  view.carry = pathsUnderTmp(named);
  view.files = defaultFiles();
  if (e.launch.network != LaunchSpec::Network::Off) {
    const NamespaceSupport net = robotNetworkSupport();
    if (net.available)
      view.network_address = (10u << 24) | (static_cast<uint32_t>(e.setup.team & 0xff) << 8) |
                             static_cast<uint32_t>(e.setup.player & 0xff);  // 10.0.<team>.<player>
    else if (e.launch.network == LaunchSpec::Network::On)
      throw ProgramError("robot " + e.slot.tag + ": network: on, but this machine gives its program no network of "
                         "its own (" + net.why + "); give network: off (the machine's network) or run where "
                         "network namespaces and /dev/net/tun are allowed (as root, or with unprivileged user "
                         "namespaces and a /dev/net/tun the user may open)",
                         e.slot.tag + ": no network namespace");
  }
  view.files.insert(view.files.end(), e.launch.files.begin(), e.launch.files.end());
  return view;
}

// A launched robot's program: started with its names, seed and setup
// filled into its command, its output in program_logs/<tag>.log. It
// attaches by name like any external program (the first tick waits).
std::unique_ptr<ProgramDriver> Programs::makeLaunched(const ProgramRun& run, const ProgramEntry& e) {
  const RobotSlot& slot = e.slot;
  const std::filesystem::path logs(run.program_logs);
  std::error_code ec;
  std::filesystem::create_directories(logs, ec);
  if (ec) throw RunnerError("program_logs: cannot create " + logs.string() + ": " + ec.message());
  const std::string config = (logs / (slot.tag + ".robot.yaml")).string();
  {
    std::ofstream out(config);
    out << ap::robotSetupYaml(e.setup);
    if (!out) throw RunnerError("program_logs: cannot write " + config);
  }
  // The body's own placeholders (libagent's names, LoLA's socket) and the run's.
  std::map<std::string, std::string> values = slot.host->placeholders();
  values.insert({{"team", std::to_string(e.setup.team)},
                 {"player", std::to_string(e.setup.player)},
                 {"seed", std::to_string(e.setup.seed)},
                 {"config", std::filesystem::absolute(config).string()}});
  const LolaView view = lolaView(e);
  if (!view.socket_placeholder.empty()) values["socket"] = view.socket_placeholder;
  const std::string& robocup = view.robocup;
  std::vector<std::string> argv;
  for (const std::string& a : e.launch.command) argv.push_back(ProgramProcess::fill(a, values));
  argv[0] = ProgramProcess::resolveCommand(argv[0], run.base_dir);
  std::vector<std::pair<std::string, std::string>> env;
  for (const auto& [k, v] : e.launch.env) env.emplace_back(k, ProgramProcess::fill(v, values));
  const std::string cwd = ProgramProcess::fill(e.launch.cwd, values);
  std::unique_ptr<ClockPage> clock = clockPage(run, e);
  std::unique_ptr<ProgramProcess> process;
  try {
    env = shimLaunchEnvironment(slot.tag, argv[0], {clock->name(), e.v4l2_block}, std::move(env));
    ProgramView view = programView(e, logs, robocup, argv, cwd, env, config);
    process = std::make_unique<ProgramProcess>(slot.tag, argv, cwd, env, (logs / (slot.tag + ".log")).string(),
                                               e.launch.stop_grace_s, std::move(view));
  } catch (const ProgramError&) {
    throw;  // already names the robot and says what (programView)
  } catch (const std::runtime_error& err) {
    throw ProgramError(err.what(), slot.tag + ": program could not be started");
  }
  return std::make_unique<LaunchedProgram>(slot, run.attach_timeout_s, std::move(clock), std::move(process));
}

// A robot whose program is started by hand. Where the machine gives
// namespaces, the run holds the view a launched program would get (its PID
// and network namespaces, /tmp, /home/nao, the default files: programView)
// in an init that starts nothing (ProgramProcess), named in the robot's
// clock page, so `simswift attach` starts its command in it
// (JoinView.hpp); a program started otherwise meets the machine as before
// (and the GameController's loopback packets: Runner::buildRobotLan).
std::unique_ptr<ProgramDriver> Programs::makeExternal(const ProgramRun& run, const ProgramEntry& e) {
  const RobotSlot& slot = e.slot;
  std::unique_ptr<ProgramProcess> view;
  ClockPage::View page_view;
  if (mountNamespaceSupport().available) {
    const std::filesystem::path logs(run.program_logs);
    std::error_code ec;
    std::filesystem::create_directories(logs, ec);
    if (ec) throw RunnerError("program_logs: cannot create " + logs.string() + ": " + ec.message());
    try {
      ProgramView v = programView(e, logs, "", {}, run.base_dir.empty() ? "." : run.base_dir, {}, logs.string());
      view = std::make_unique<ProgramProcess>(slot.tag, std::vector<std::string>{}, "",
                                              std::vector<std::pair<std::string, std::string>>{},
                                              (logs / (slot.tag + ".view.log")).string(), e.launch.stop_grace_s, v);
      page_view = {view->pid(), v.folder};
    } catch (const ProgramError&) {
      throw;
    } catch (const std::runtime_error& err) {
      throw ProgramError(err.what(), slot.tag + ": its view could not be made");
    }
  }
  return std::make_unique<ExternalProgram>(slot, run.attach_timeout_s, clockPage(run, e, page_view), std::move(view));
}

ap::RobotProgram* Programs::program(int i) const {
  if (i < 0 || i >= size() || !robots_[i].driver) return nullptr;
  auto* b = dynamic_cast<BuiltinProgram*>(robots_[i].driver.get());
  return b ? &b->program() : nullptr;
}

std::vector<std::string> Programs::logs() const {
  std::vector<std::string> out;
  for (const Robot& r : robots_)
    if (r.driver && !r.driver->log().empty()) out.push_back(r.driver->log());
  return out;
}

// Launched programs see `shutdown` (simswift-agent exits); any other gets
// SIGTERM, then SIGKILL after its stop_grace. Reaped before the hosts
// remove their objects. Then builtin threads are joined.
void Programs::shutdown() {
  for (Robot& r : robots_)
    if (r.driver) r.driver->stop();
  for (Robot& r : robots_)
    if (r.driver) r.driver->join();
}

}  // namespace simswift::programs
