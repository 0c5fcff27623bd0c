#include "sim/runner/Scenario.hpp"

#include <dlfcn.h>
#include <link.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>

#include "common/config/Seed.hpp"
#include "common/libagent/SharedNames.hpp"
#include "common/nao/NaoFacts.hpp"
#include "common/random/DeriveSeed.hpp"
#include "sim/game/GameControlVersions.hpp"
#include "sim/runner/Bodies.hpp"
#include "sim/world/ConfigError.hpp"

// The data folder's path below an install prefix (CMAKE_INSTALL_DATADIR,
// relative), the same in the build tree's staged copy (CMakeLists.txt).
#ifndef SIMSWIFT_DATA_SUBDIR
#define SIMSWIFT_DATA_SUBDIR "share/simswift"
#endif

namespace simswift::runner {

namespace al = common::libagent;
using programs::ProgramProcess;

namespace {

// The file holding this code: libsimswift.so for the library and the Python
// module (which loads it), or the executable that links the simulator
// statically (simswift, the tests). Symlinks and "..", as a loader's
// $ORIGIN search path leaves them, resolved.
std::filesystem::path codeFile() {
  std::error_code ec;
  Dl_info info{};
  link_map* map = nullptr;
  std::filesystem::path file;
  if (dladdr1(reinterpret_cast<void*>(&dataDirs), &info, reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP) &&
      map && map->l_name && *map->l_name)
    file = map->l_name;  // a shared library
  else
    file = std::filesystem::read_symlink("/proc/self/exe", ec);  // the executable itself
  if (file.empty()) return {};
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(file, ec);
  return ec ? std::filesystem::absolute(file, ec).lexically_normal() : canonical;
}

}  // namespace

// The one rule (docs/library.md, "Where the data is"): $SIMSWIFT_DATA_DIR if
// set, else the nearest share/simswift beside the code's file: in its
// folder, its parent or its grandparent. Installed anywhere (and moved):
// <prefix>/lib/libsimswift.so, <prefix>/lib/<multiarch>/libsimswift.so and
// <prefix>/bin/simswift find <prefix>/share/simswift; in the build tree
// build/libsimswift.so, build/simswift and build/tests/test_x find the
// staged copy build/share/simswift. Nothing compiled in, nothing from the
// working folder or the Python interpreter's.
std::vector<std::string> dataDirs() {
  if (const char* env = std::getenv("SIMSWIFT_DATA_DIR"); env && *env) return {env};
  const std::filesystem::path code = codeFile();
  if (code.empty()) return {};
  std::vector<std::string> candidates;
  std::error_code ec;
  for (std::filesystem::path dir = code.parent_path(); candidates.size() < 3; dir = dir.parent_path()) {
    const std::filesystem::path c = dir / SIMSWIFT_DATA_SUBDIR;
    if (std::filesystem::is_directory(c, ec)) return {c.string()};
    candidates.push_back(c.string());
    if (dir == dir.parent_path()) break;
  }
  return candidates;  // none exists: the error lists where it looked
}

// Sane ranges for scenario values (SI units unless noted).
namespace limits {
constexpr double kMaxTime = 1e6;           // s: durations and event times (11.6 days)
constexpr double kMinDuration = kTickSeconds;  // s: at least one tick
constexpr double kMaxPosition = 50;        // m: before the field is known
constexpr double kMaxHeading = 2 * M_PI;   // rad
constexpr double kMaxJointAngle = 10;      // rad (the servos clamp to the joint's range)
constexpr double kRobotRadius = common::nao::kFootprintRadius / 1000;  // m
}  // namespace limits

namespace {

// The names a scenario may use, each list once (parsePosture in agent/
// maps them to the robot code's enum; actions: agent/motion/ActionYaml).
struct ButtonName {
  const char* name;
  sensors::Button button;
};
const ButtonName kButtonNames[] = {{"chest", sensors::Button::Chest},
                                   {"head_front", sensors::Button::HeadFront},
                                   {"head_middle", sensors::Button::HeadMiddle},
                                   {"head_rear", sensors::Button::HeadRear}};

std::string resolve(const std::string& base, const std::string& p) {
  if (p.empty() || p[0] == '/' || base.empty()) return p;
  return base + "/" + p;
}

sensors::Button buttonNamed(const YamlReader& r, const std::string& key) {
  std::vector<std::string> names;
  for (const ButtonName& n : kButtonNames) names.push_back(n.name);
  const std::string name = r.choice(key, "chest", names);
  for (const ButtonName& n : kButtonNames)
    if (name == n.name) return n.button;
  return sensors::Button::Chest;
}

// A click as a finger makes it: 0.1 s down, 0.1 s up (libagent counts a
// series while the button is up for at most 18 cycles, 0.18 s, between).
constexpr double kClickDown = 0.1, kClickUp = 0.1;  // s

// One entry of a robot's `actions:` list (its t already read, s) that is
// not the program's: a push, or a button click or press (they act on the
// body from outside, so any robot program takes them). False for a body
// action (agent/program's reader takes it).
bool readBodyEvent(const YamlReader& r, double t, RobotSpec& rs) {
  const int kinds = r.has("action") + r.has("push") + r.has("click") + r.has("press");
  if (kinds > 1) r.fail("an actions entry holds one of 'action', 'push', 'click' or 'press'");
  if (r.has("click")) {
    const sensors::Button b = buttonNamed(r, "click");
    const int count = r.integer("count", 1, Range::closed(1, 8));  // ButtonPresses holds 8 bits
    for (int k = 0; k < count; ++k)
      rs.buttons.push_back({t + k * (kClickDown + kClickUp), kClickDown, b});
    r.finish();
    return true;
  }
  if (r.has("press")) {
    const sensors::Button b = buttonNamed(r, "press");
    const double held = r.number("for", Range::closed(0.01, limits::kMaxTime));  // s
    rs.buttons.push_back({t, held, b});
    r.finish();
    return true;
  }
  if (r.has("push")) {
    if (r.has("action")) r.fail("an actions entry holds either 'action' or 'push', not both");
    YamlReader p = r.map("push");
    RobotSpec::Push push;
    push.t_s = t;
    const Range impulse = Range::closed(-World::kMaxPushImpulse, World::kMaxPushImpulse);  // N*s
    push.jx = p.number("x", push.jx, impulse);
    push.jy = p.number("y", push.jy, impulse);
    if (std::hypot(push.jx, push.jy) > World::kMaxPushImpulse)
      p.fail("x", "the push's impulse must be at most " + std::to_string(World::kMaxPushImpulse) + " N*s");
    p.finish();
    rs.pushes.push_back(push);
    r.finish();
    return true;
  }
  return false;
}

// The program's keys of a robot map into rs.setup, its body events into rs.
void readProgramKeys(const YamlReader& robot, RobotSpec& rs) {
  programs::readProgramPart(robot, rs.setup,
                            [&rs](const YamlReader& entry, double t) { return readBodyEvent(entry, t, rs); });
  std::stable_sort(rs.pushes.begin(), rs.pushes.end(),
                   [](const RobotSpec::Push& a, const RobotSpec::Push& b) { return a.t_s < b.t_s; });
}

// One entry of a robot's `buttons:` list.
RobotSpec::ButtonPress readButton(const YamlReader& r) {
  RobotSpec::ButtonPress b;
  b.t_s = r.number("t", Range::closed(0, limits::kMaxTime));
  b.duration_s = r.number("duration", b.duration_s, Range::closed(0, limits::kMaxTime));
  b.button = buttonNamed(r, "button");
  r.finish();
  return b;
}

// libagent: {start: stiff | limp, release: 2016 | 2017 | 2018}
void readLibagent(const YamlReader& r, RobotSpec& rs) {
  rs.start = r.enumChoice("start", rs.start, {{"stiff", bridge::StartMode::Stiff}, {"limp", bridge::StartMode::Limp}});
  const int year = r.integer("release", bridge::releaseYear(rs.release), Range::closed(0, 1000000));
  if (!bridge::parseRelease(year, &rs.release))
    r.fail("release", "expected one of 2016, 2017, 2018 (the rUNSWift releases for the NAO V5; got " +
                          std::to_string(year) + ")");
  r.finish();
}

}  // namespace

// team_comms: {loss, delay_ms, budget}
network::TeamNetworkConfig readTeamComms(const YamlReader& r) {
  network::TeamNetworkConfig c;
  c.loss = r.number("loss", c.loss, Range::closed(0, 1));
  c.delay_ms = r.number("delay_ms", c.delay_ms, Range::closed(0, 60000));
  c.budget = r.integer("budget", static_cast<int>(c.budget), Range::nonNegative());
  r.finish();
  return c;
}

// game: the GameController's timeline and penalties (robots already read).
game::GameConfig readGame(const YamlReader& r, int num_robots) {
  game::GameConfig g;
  auto state = [](const YamlReader& m, const std::string& key, game::GameStateValue def) {
    game::GameStateValue v;
    game::parseState(m.choice(key, game::stateName(def), game::stateNames()), &v);
    return v;
  };
  g.initial_state = state(r, "state", g.initial_state);
  g.kickoff_team = r.integer("kickoff_team", g.kickoff_team, Range::closed(0, 1));
  g.half_duration_s = r.number("half_duration", g.half_duration_s, Range::closed(1, 3600));
  g.first_half = r.boolean("first_half", g.first_half);
  using Return = game::GameConfig::Return;
  g.on_unpenalise =
      r.enumChoice("on_unpenalise", g.on_unpenalise, {{"previous", Return::Previous}, {"sideline", Return::Sideline}});
  double last = 0;
  for (const YamlReader& e : r.list("timeline")) {
    game::GameConfig::StateChange c;
    c.t_s = e.number("t", Range::nonNegative());
    if (c.t_s < last) e.fail("t", "timeline entries must be in time order");
    last = c.t_s;
    if (!e.has("state")) e.fail("state", "a timeline entry needs a state");
    c.state = state(e, "state", c.state);
    c.secondary = e.enumChoice("secondary", c.secondary,
                               {{"normal", game::SecondaryState::Normal},
                                {"penalty_shoot", game::SecondaryState::PenaltyShoot},
                                {"overtime", game::SecondaryState::Overtime},
                                {"timeout", game::SecondaryState::Timeout}});
    c.kickoff_team = e.integer("kickoff_team", c.kickoff_team, Range::closed(-1, 1));
    e.finish();
    g.timeline.push_back(c);
  }
  last = 0;
  for (const YamlReader& e : r.list("penalties")) {
    game::GameConfig::PenaltyEvent p;
    p.t_s = e.number("t", Range::nonNegative());
    if (p.t_s < last) e.fail("t", "penalties must be in time order");
    last = p.t_s;
    p.robot = e.integer("robot", Range::nonNegative());
    if (p.robot >= num_robots)
      e.fail("robot", "no robot " + std::to_string(p.robot) + " (the scenario has " + std::to_string(num_robots) +
                          "; robot is the index in robots:)");
    game::parsePenalty(e.choice("penalty", game::penaltyName(p.penalty), game::penaltyNames()), &p.penalty);
    p.duration_s = e.number("duration", p.duration_s, Range::atLeast(-1));
    e.finish();
    g.penalties.push_back(p);
  }
  // udp: the SPL GameController's packets on the loopback network (ports
  // and address mean nothing without it, so they are refused alone).
  g.udp.on = r.boolean("udp", g.udp.on);
  for (const char* key : {"address", "port", "return_port", "version", "message_budget"})
    if (!g.udp.on && r.has(key)) r.fail(key, "needs udp: on");
  g.udp.address = r.string("address", g.udp.address);
  if (!game::isLoopbackAddress(g.udp.address))
    r.fail("address", "must be an IPv4 address in 127.0.0.0/8 (the loopback network; got '" + g.udp.address + "')");
  g.udp.port = r.integer("port", g.udp.port, Range::closed(1, 65535));
  g.udp.return_port = r.integer("return_port", g.udp.return_port, Range::closed(0, 65535));
  if (g.udp.return_port == g.udp.port) r.fail("return_port", "must differ from port");
  // The packet version of the season the robot programs were written for
  // (sim/game/GameControlVersions.hpp).
  g.udp.version = r.integer("version", g.udp.version, Range::closed(0, 255));
  if (!game::spl::findPacketVersion(g.udp.version))
    r.fail("version", "simswift sends GameController packet versions " + game::spl::packetVersionList() +
                          " (got " + std::to_string(g.udp.version) + ")");
  g.udp.message_budget = r.integer("message_budget", g.udp.message_budget, Range::closed(0, 65535));
  // A penalty the season's packets have no number for (kick_off_goal from
  // 2020 on) cannot reach the programs: refused.
  if (g.udp.on) {
    const game::spl::PacketVersion& v = *game::spl::findPacketVersion(g.udp.version);
    size_t k = 0;
    for (const YamlReader& e : r.list("penalties")) {
      if (game::spl::penaltyCode(v, g.penalties[k].penalty) < 0)
        e.fail("penalty", "GameController packet version " + std::to_string(v.data_version) + " (" + v.seasons +
                              ") has no such penalty");
      ++k;
    }
  }
  r.finish();
  return g;
}

// inertial: the raw slots' signs against the calibrated ones (+1 or -1).
static void readInertial(const YamlReader& top, Scenario& sc) {
  const std::optional<YamlReader> r = top.optionalMap("inertial");
  if (!r) return;
  auto sign = [&](const char* key, int def) {
    const int v = r->integer(key, def);
    if (v != 1 && v != -1) r->fail(key, "must be 1 or -1, got " + std::to_string(v));
    return v;
  };
  sc.gyr_raw_sign = sign("gyr_raw_sign", sc.gyr_raw_sign);
  sc.acc_raw_sign = sign("acc_raw_sign", sc.acc_raw_sign);
  r->finish();
}

// noise: on/off, or a map of switches.
void readNoise(const YamlReader& top, NoiseSwitches& noise) {
  if (!top.has("noise")) return;
  if (top.node()["noise"].IsMap()) {
    YamlReader n = top.map("noise");
    const NoiseSwitches d;  // a map sets every switch: absent ones are on
    noise.on = n.boolean("enabled", d.on);
    noise.gyro = n.boolean("gyro", d.gyro);
    noise.accel = n.boolean("accel", d.accel);
    noise.angle = n.boolean("angle", d.angle);
    noise.fsr = n.boolean("fsr", d.fsr);
    noise.sonar = n.boolean("sonar", d.sonar);
    noise.encoder = n.boolean("encoder", d.encoder);
    n.finish();
  } else {
    noise.on = top.boolean("noise");
  }
}

namespace {

// physics: the World's settings a user may tune, each key its WorldConfig
// field's name but `iterations` (quick_iterations, its key from before:
// kRenamedKeys). The ranges are checkWorldConfig's (sim/world/World.hpp).
struct PhysicsInt {
  const char* key;
  int WorldConfig::*field;
};
struct PhysicsNumber {
  const char* key;
  double WorldConfig::*field;
};
const PhysicsInt kPhysicsInts[] = {
    {"substeps", &WorldConfig::substeps},
    {"iterations", &WorldConfig::quick_iterations},
    {"joint_projection_sweeps", &WorldConfig::joint_projection_sweeps},
    {"sole_nx", &WorldConfig::sole_nx},
    {"sole_ny", &WorldConfig::sole_ny},
};
const PhysicsNumber kPhysicsNumbers[] = {
    {"quick_w", &WorldConfig::quick_w},
    {"erp", &WorldConfig::erp},
    {"cfm", &WorldConfig::cfm},
    {"joint_projection_tolerance", &WorldConfig::joint_projection_tolerance},
    {"sole_stiffness", &WorldConfig::sole_stiffness},
    {"sole_damping", &WorldConfig::sole_damping},
    {"sole_anchor_erp", &WorldConfig::sole_anchor_erp},
    {"sole_anchor_slip", &WorldConfig::sole_anchor_slip},
};
// checkWorldConfig names the field; the file's key differs only here.
const std::pair<const char*, const char*> kRenamedKeys[] = {{"quick_iterations", "iterations"}};

}  // namespace

// physics: {substeps, solver, iterations, ...}; absent keys keep world's.
void readPhysics(const YamlReader& top, WorldConfig& world) {
  const std::optional<YamlReader> p = top.optionalMap("physics");
  if (!p) return;
  world.solver = p->enumChoice("solver", world.solver,
                               {{"quick", WorldConfig::Solver::Quick}, {"exact", WorldConfig::Solver::Exact}});
  for (const PhysicsInt& k : kPhysicsInts) world.*k.field = p->integer(k.key, world.*k.field);
  for (const PhysicsNumber& k : kPhysicsNumbers) world.*k.field = p->number(k.key, world.*k.field);
  p->finish();
  const std::optional<WorldConfigProblem> bad = checkWorldConfig(world);
  if (!bad) return;
  std::string key = bad->field;  // a field the file cannot set (tick_us) is named as itself
  for (const auto& [field, file_key] : kRenamedKeys)
    if (bad->field == field) key = file_key;
  p->fail(key, bad->why);
}

// program: {files: {PATH: CONTENT, PATH: {from: FILE_OR_FOLDER}}}: the
// robot's files its program sees (sim/programs/ProgramView.hpp).
std::vector<programs::FileEntry> readFiles(const YamlReader& files, const std::string& base_dir) {
  std::vector<programs::FileEntry> out;
  for (const auto& kv : files.node()) {
    if (!kv.first.IsScalar()) files.fail("every key must be a path");
    const std::string path = kv.first.Scalar();
    (void)files.has(path);
    if (const std::string why = programs::fileEntryProblem(path); !why.empty()) files.fail(path, why);
    programs::FileEntry e;
    e.path = path;
    const common::config::ConfigPlace at = files.place(path);
    e.where = at.file + ":" + std::to_string(at.line);
    if (kv.second.IsScalar()) {
      e.content = kv.second.Scalar();
    } else if (kv.second.IsMap()) {
      const YamlReader m = files.map(path);
      e.from = m.string("from", "");
      if (e.from.empty()) m.missing("from", "a file or folder of the machine to map in (or give the content as a string)");
      if (e.from[0] != '/') e.from = (std::filesystem::path(base_dir.empty() ? "." : base_dir) / e.from).lexically_normal().string();
      std::error_code ec;
      if (!std::filesystem::exists(e.from, ec)) m.fail("from", "no such file or folder: " + e.from);
      m.finish();
    } else {
      files.fail(path, "expected the file's content (a string) or {from: PATH}");
    }
    auto inside = [](const std::string& a, const std::string& b) {  // a below b
      return a.size() > b.size() && a.compare(0, b.size(), b) == 0 && a[b.size()] == '/';
    };
    for (const programs::FileEntry& o : out) {
      if (!o.from.empty() && inside(e.path, o.path)) files.fail(path, "is inside " + o.path + ", a folder mapped in");
      if (!e.from.empty() && inside(o.path, e.path))
        files.fail(path, "would cover " + o.path + " (given above): map the folder in, or give its files");
    }
    if (e.path == "/home/nao" && e.from.empty()) files.fail(path, "/home/nao is a folder: map one in with {from: PATH}");
    out.push_back(std::move(e));
  }
  return out;
}

void readProgram(const YamlReader& robot, RobotSpec& rs, const std::string& base_dir, bool any_body) {
  rs.program = RobotSpec::Program::Builtin;
  if (!robot.has("program") || !robot.node()["program"].IsMap()) {
    rs.program = robot.enumChoice("program", rs.program,
                                  {{"builtin", RobotSpec::Program::Builtin}, {"external", RobotSpec::Program::External}});
    return;
  }
  rs.program = RobotSpec::Program::External;
  const YamlReader p = robot.map("program");
  const YAML::Node cmd = p.node()["command"];
  if (!cmd.IsDefined()) p.fail("command", "a launched program needs command: [path, args...]");
  if (!cmd.IsSequence() || cmd.size() == 0) p.fail("command", "must be a non-empty list: [path, args...]");
  for (const YAML::Node& a : cmd) {
    if (!a.IsScalar()) p.fail("command", "every element must be a string");
    rs.launch.command.push_back(a.Scalar());
  }
  (void)p.has("command");
  rs.launch.cwd = p.string("cwd", rs.launch.cwd);
  if (!rs.launch.cwd.empty() && rs.launch.cwd[0] != '/')
    rs.launch.cwd = (std::filesystem::path(base_dir.empty() ? "." : base_dir) / rs.launch.cwd).string();
  if (rs.launch.cwd.empty()) rs.launch.cwd = base_dir.empty() ? "." : base_dir;
  if (auto env = p.optionalMap("env")) {
    for (const YamlReader::Key& k : env->keys()) {
      const std::string& key = k.name;
      if (key.empty() || key.find('=') != std::string::npos) env->fail(key, "not an environment variable name");
      rs.launch.env.emplace_back(key, env->string(key));
    }
  }
  rs.launch.stop_grace_s = p.number("stop_grace", rs.launch.stop_grace_s, Range::closed(0, 60));
  if (auto files = p.optionalMap("files")) rs.launch.files = readFiles(*files, base_dir);
  rs.launch.network = p.enumChoice("network", rs.launch.network,
                                   {{"auto", programs::LaunchSpec::Network::Auto},
                                    {"on", programs::LaunchSpec::Network::On},
                                    {"off", programs::LaunchSpec::Network::Off}});
  // Placeholders are checked now, not when the run starts: the run's, and
  // the body's (BodySide::placeholders: a LoLA body's socket, libagent's names).
  std::map<std::string, std::string> names;
  for (const char* k : {"team", "player", "seed", "config"}) names[k] = "x";
  const bool lola = robot.has("lola");
  if (lola || any_body) names["socket"] = "x";
  if (!lola || any_body)
    for (const char* k : {"number", "memory", "semaphore", "extension"}) names[k] = "x";
  try {
    for (const std::string& a : rs.launch.command) ProgramProcess::fill(a, names);
    ProgramProcess::fill(rs.launch.cwd, names);
    for (const auto& [k, v] : rs.launch.env) ProgramProcess::fill(v, names);
  } catch (const std::runtime_error& e) {
    p.fail("command", e.what());
  }
  p.finish();
}

uint64_t programSeed(uint64_t seed, int index) {
  using common::random::deriveSeed;
  return deriveSeed(deriveSeed(seed, common::random::seed_tag::kRobotProgram), static_cast<uint64_t>(index));
}

programs::ProgramIdentity programIdentity(const Scenario& sc, int index) {
  const RobotSpec& r = sc.robots[index];
  programs::ProgramIdentity id;
  id.team = r.team;
  id.player = r.player;
  id.seed = programSeed(sc.seed, index);
  id.posture = r.posture;
  id.x = r.x;  // m
  id.y = r.y;
  id.theta = r.theta;  // rad
  id.pushed = !r.pushes.empty();
  return id;
}

void readActions(const YamlReader& robot, RobotSpec& rs) {
  programs::readProgramActions(robot, rs.setup,
                               [&rs](const YamlReader& entry, double t) { return readBodyEvent(entry, t, rs); });
  std::stable_sort(rs.pushes.begin(), rs.pushes.end(),
                   [](const RobotSpec::Push& a, const RobotSpec::Push& b) { return a.t_s < b.t_s; });
}

bool RobotSpec::buttonHeld(sensors::Button b, double t_s) const {
  for (const ButtonPress& p : buttons)
    if (p.button == b && t_s >= p.t_s - 1e-9 && t_s < p.t_s + p.duration_s - 1e-9) return true;
  return false;
}

// A relative path: the scenario's folder (or base_dir) first, then the data
// folders; never the source tree this binary was built from.
std::string Scenario::locate(const std::string& p, const std::string& key, int line) const {
  if (p.empty() || p[0] == '/') return p;
  std::vector<std::string> tried;
  for (const std::string& dir : [&] {
         std::vector<std::string> d{base_dir.empty() ? "." : base_dir};
         for (const std::string& x : dataDirs()) d.push_back(x);
         return d;
       }()) {
    const std::string c = resolve(dir, p);
    std::error_code ec;
    if (std::filesystem::exists(c, ec)) return c;
    tried.push_back(c);
  }
  std::string list;
  for (const auto& t : tried) list += (list.empty() ? "" : ", ") + t;
  throw ConfigError(source, line, key,
                    "'" + p + "' not found (tried " + list + "; set SIMSWIFT_DATA_DIR or give --" + key + ")");
}

std::string Scenario::modelFile() const { return locate(model_path, "model", model_line); }
std::string Scenario::fieldFile() const { return locate(field_path, "field", field_line); }

Scenario Scenario::loadFile(const std::string& path) {
  return parse(YamlReader::readFile(path, "scenario file"), path);
}

namespace {

// The run's own settings: where its files are, how long, the seed, the
// wall-clock limits and the launched programs' log folder.
void readRun(const YamlReader& top, Scenario& sc) {
  const YAML::Node& root = top.node();
  // Relative paths resolve against the scenario file's folder first.
  sc.base_dir = top.string("base_dir", std::filesystem::path(sc.source).parent_path().string());
  sc.model_path = top.string("model", sc.model_path);
  sc.field_path = top.string("field", sc.field_path);
  auto lineOf = [&](const char* key) { return root[key] ? root[key].Mark().line + 1 : 1; };
  sc.model_line = lineOf("model");
  sc.model_named = top.has("model");
  sc.field_line = lineOf("field");
  // At least one tick, at most limits::kMaxTime (a run that would go on
  // for weeks is a typo).
  sc.duration = top.number("duration", sc.duration, Range::closed(limits::kMinDuration, limits::kMaxTime));
  sc.seed = common::config::readSeed(top, "seed", sc.seed);  // all 64 bits, exact (not a YAML number)
  if (top.has("watchdog") && root["watchdog"].IsScalar() &&
      (root["watchdog"].Scalar() == "off" || root["watchdog"].Scalar() == "false")) {
    sc.watchdog_s = 0;  // off: a run that sits at a debugger breakpoint is not ended
  } else {
    sc.watchdog_s = top.number("watchdog", sc.watchdog_s, Range::openClosed(0, kMaxWallClockS));
  }
  sc.attach_timeout_s = top.number("attach_timeout", sc.attach_timeout_s, Range::openClosed(0, kMaxWallClockS));
  sc.program_logs = top.string("program_logs", sc.program_logs);
  // Whole seconds, 1970 to 2100 (a YAML number is exact there).
  const double epoch = top.number("clock_epoch", static_cast<double>(sc.clock_epoch_s), Range::closed(0, 4102444800.0));
  if (epoch != static_cast<double>(static_cast<int64_t>(epoch))) top.fail("clock_epoch", "must be whole seconds since 1970");
  sc.clock_epoch_s = static_cast<int64_t>(epoch);
  if (sc.program_logs.empty()) top.fail("program_logs", "must name a folder");
}

}  // namespace

const std::vector<std::pair<std::string, common::libagent::ImageSize>>& cameraResolutions() {
  static const std::vector<std::pair<std::string, common::libagent::ImageSize>> sizes = {
      {"640x480", {640, 480}}, {"1280x960", {1280, 960}}};
  return sizes;
}

std::optional<common::libagent::ImageSize> cameraResolution(const std::string& name) {
  for (const auto& [n, size] : cameraResolutions())
    if (n == name) return size;
  return std::nullopt;
}

namespace {

// camera: the robots' cameras and the overview. Returns the overview's
// reader, kept for errors about overview.robot once the robots are known.
std::optional<YamlReader> readCamera(const YamlReader& top, CameraSpec& camera) {
  std::optional<YamlReader> overview_reader;
  if (auto c = top.optionalMap("camera")) {
    camera.enabled = c->boolean("enabled", camera.enabled);
    // resolution: WxH sets both cameras; {top: WxH, bottom: WxH} each.
    if (c->has("resolution") && c->node()["resolution"].IsMap()) {
      const YamlReader r = c->map("resolution");
      camera.resolution[0] = r.enumChoice("top", camera.resolution[0], cameraResolutions());
      camera.resolution[1] = r.enumChoice("bottom", camera.resolution[1], cameraResolutions());
      r.finish();
    } else if (c->has("resolution")) {
      const common::libagent::ImageSize both = c->enumChoice("resolution", camera.resolution[0], cameraResolutions());
      camera.resolution[0] = camera.resolution[1] = both;
    }
    if (auto o = c->optionalMap("overview")) {
      CameraSpec::Overview& ov = camera.overview;
      ov.enabled = o->boolean("enabled", true);  // an overview: map asks for one
      using Mode = CameraSpec::Overview::Mode;
      ov.mode = o->enumChoice("mode", ov.mode, {{"fixed", Mode::Fixed}, {"robot", Mode::Robot}, {"ball", Mode::Ball}});
      ov.robot = o->integer("robot", ov.robot, Range::nonNegative());
      ov.rate_hz = o->number("rate_hz", ov.rate_hz, Range::closed(0.1, 100));
      ov.width = o->integer("width", ov.width, Range::closed(16, 3840));
      ov.height = o->integer("height", ov.height, Range::closed(16, 2160));
      if (ov.width % 2 || ov.height % 2) o->fail("width", "width and height must be even (video encoders)");
      ov.dir = o->string("dir", ov.dir);
      overview_reader = *o;
      o->finish();
    }
    c->finish();
  }
  return overview_reader;
}

// vision: on/off, or the detector model's map (sim/vision/VisionConfig.hpp).
void readVision(const YamlReader& top, vision::VisionConfig& vision) {
  if (!top.has("vision")) return;
  if (top.node()["vision"].IsMap())
    vision = vision::readVisionConfig(top.map("vision"), vision);
  else
    vision.enabled = top.boolean("vision");
}

// ball: {x, y} (m, field frame), or none.
void readBall(const YamlReader& top, Scenario& sc) {
  const YAML::Node& root = top.node();
  if (root["ball"] && root["ball"].IsScalar()) {
    // The only scalar a ball takes: a world without one (a search with
    // nothing to find), rather than a ball parked somewhere out of sight.
    if (top.choice("ball", "none", {"none"}) == "none") sc.no_ball = true;
  } else if (auto b = top.optionalMap("ball")) {
    const Range pos = Range::closed(-limits::kMaxPosition, limits::kMaxPosition);
    sc.ball = std::make_pair(b->number("x", pos), b->number("y", pos));
    sc.ball_line = b->node().Mark().line + 1;
    b->finish();
  }
}

// What the robots read so far have taken: libagent names and team colours.
struct RobotClaims {
  std::set<int> numbers;                          // libagent name numbers in use
  std::set<std::string> memories;                 // libagent memory names and LoLA sockets in use
  std::vector<std::pair<int, TeamColour>> teams;  // team number -> colour, in order of appearance
  int bare = 0;                                   // robots with the bare names
  std::optional<bridge::BodyInterface> body;      // the first robot's body interface
};

// team, player and colour: one entry per player, two teams, one colour each.
void readTeamPlayer(const YamlReader& r, RobotSpec& rs, RobotClaims& claims) {
  std::vector<std::pair<int, TeamColour>>& teams = claims.teams;
  rs.team = r.integer("team", Range::closed(al::kMinTeamNumber, al::kMaxTeamNumber));
  rs.player = r.integer("player", Range::closed(al::kMinPlayer, al::kMaxPlayer));
  if (!claims.numbers.insert(al::simulationNumber(rs.team, rs.player)).second)
    r.fail("player", "team " + std::to_string(rs.team) + " player " + std::to_string(rs.player) +
                         " appears twice");
  auto known = std::find_if(teams.begin(), teams.end(), [&](const auto& t) { return t.first == rs.team; });
  if (r.has("colour")) {
    rs.colour = r.choice("colour", "blue", {"blue", "red"}) == "blue" ? TeamColour::Blue : TeamColour::Red;
  } else if (known != teams.end()) {
    rs.colour = known->second;
  } else {
    rs.colour = teams.empty() || teams.front().second == TeamColour::Red ? TeamColour::Blue : TeamColour::Red;
  }
  if (known != teams.end() && known->second != rs.colour)
    r.fail("colour", "team " + std::to_string(rs.team) + " already plays in " +
                         (known->second == TeamColour::Blue ? "blue" : "red"));
  if (known == teams.end()) {
    if (teams.size() == 2) r.fail("team", "a match has two teams (" + std::to_string(teams[0].first) + " and " +
                                              std::to_string(teams[1].first) + ")");
    if (!teams.empty() && teams.front().second == rs.colour)
      r.fail("colour", "team " + std::to_string(teams.front().first) + " already plays in " +
                           (rs.colour == TeamColour::Blue ? "blue" : "red"));
    teams.emplace_back(rs.team, rs.colour);
  }
}

// lola: {socket: PATH}: the NAO V6's LoLA body; every robot of a run ticks
// alike, so its interface is the first robot's.
void readLola(const YamlReader& r, RobotSpec& rs, RobotClaims& claims) {
  const std::optional<YamlReader> l = r.optionalMap("lola");
  if (l && r.has("libagent"))
    r.fail("lola", "a robot has one body interface: libagent (the NAO V5) or lola (the NAO V6), not both");
  rs.body = l ? bridge::BodyInterface::Lola : bridge::BodyInterface::Libagent;
  if (!claims.body) claims.body = rs.body;
  if (*claims.body != rs.body) {
    const int64_t first = bodyCycleUs(*claims.body), here = bodyCycleUs(rs.body);
    r.fail(l ? "lola" : "team", std::string("every robot of a run ticks alike: robots[0] has a ") +
                                    bodyInterfaceName(*claims.body) + " body (" + std::to_string(first / 1000) +
                                    " ms), this one " + bodyInterfaceName(rs.body) + " (" +
                                    std::to_string(here / 1000) + " ms)");
  }
  if (!l) return;
  rs.lola_socket = l->string("socket", defaultLolaSocket(rs.team, rs.player, rs.bare_names));
  if (rs.lola_socket.empty()) l->fail("socket", "must name a path");
  rs.lola_socket = std::filesystem::absolute(rs.lola_socket).lexically_normal().string();
  if (rs.lola_socket.size() > 107)
    l->fail("socket", "a Unix socket path has at most 107 characters (" + rs.lola_socket + " has " +
                          std::to_string(rs.lola_socket.size()) + ")");
  l->finish();
  if (!claims.memories.insert(rs.lola_socket).second) r.fail("lola", "two robots would share " + rs.lola_socket);
}

// libagent and names: the release's block and its shared-memory names, no
// two robots on one name.
void readNames(const YamlReader& r, RobotSpec& rs, RobotClaims& claims) {
  if (auto l = r.optionalMap("libagent")) readLibagent(*l, rs);
  rs.bare_names = r.choice("names", "simulation", {"simulation", "bare"}) == "bare";
  if (r.has("lola")) return;  // no libagent names (readLola, after the program)
  if (rs.release == bridge::Release::R2016) {
    if (r.has("names") && !rs.bare_names)
      r.fail("names", "rUNSWift 2016 has only the robot build's names (/libagent-memory): names: bare");
    rs.bare_names = true;
  }
  if (rs.bare_names && ++claims.bare > 1)
    r.fail("names", "only one robot can have the bare names (/libagent-memory)");
  const std::string memory = bridge::releaseNames(rs.release, rs.team, rs.player, rs.bare_names).memory;
  if (!claims.memories.insert(memory).second) r.fail("libagent", "two robots would share " + memory);
}

// x, y, theta (m, m, rad; field frame) and the start posture.
void readPlacement(const YamlReader& r, RobotSpec& rs) {
  const Range pos = Range::closed(-limits::kMaxPosition, limits::kMaxPosition);
  rs.x = r.number("x", rs.x, pos);
  rs.y = r.number("y", rs.y, pos);
  rs.theta = r.number("theta", rs.theta, Range::closed(-limits::kMaxHeading, limits::kMaxHeading));
  rs.posture = *common::nao::parsePosture(r.choice("posture", "stand", common::nao::postureNames()));
}

// buttons, then script, actions and behaviour: what the robot is told to
// do over time. Joints, Motion actions and behaviours need a program
// simswift composes or configures; pushes and buttons any.
void readTimedLists(const YamlReader& r, RobotSpec& rs) {
  if (r.has("buttons"))
    for (const YamlReader& b : r.list("buttons")) rs.buttons.push_back(readButton(b));
  const bool own_program = rs.program == RobotSpec::Program::External && !rs.launch.launched();
  if (own_program && r.has("script"))
    r.fail("script", "an external robot runs its own program; a script needs program: builtin (or a "
                     "launched program, which gets it in its {config} file)");
  if (own_program && r.has("behaviour"))
    r.fail("behaviour", "an external robot runs its own program; a behaviour needs program: builtin (or a "
                        "launched program, which gets it in its {config} file)");
  readProgramKeys(r, rs);
  const programs::ProgramPart& p = rs.setup;
  if (own_program && !p.actions.empty())
    r.fail("actions", "an external robot runs its own program; body actions need program: builtin "
                      "or a launched program, which gets them in its {config} file (pushes, clicks and "
                      "presses are fine)");
  if (!p.actions.empty() && !p.script.empty())
    r.fail("actions", "a robot takes either 'script' (joints) or 'actions' (Motion)");
  if (p.behaviour && !p.actions.empty())
    r.fail("actions", std::string("a robot with behaviour ") + programs::behaviourName(p) +
                          " takes no body actions (pushes only); use behaviour: script");
  if (p.behaviour && !p.script.empty()) r.fail("script", "a robot with a behaviour takes no joint script");
}

// The builtin program speaks the 2017 block only.
void checkBuiltinRelease(const YamlReader& r, const RobotSpec& rs) {
  if (rs.program == RobotSpec::Program::Builtin && rs.release != bridge::Release::R2017)
    r.fail("libagent", "the builtin robot program speaks the 2017 block; release " +
                           std::to_string(bridge::releaseYear(rs.release)) + " needs program: external");
}

}  // namespace

std::array<std::string, 2> defaultCameraDevices(bridge::BodyInterface body) {
  if (body == bridge::BodyInterface::Lola) return {"/dev/video-top", "/dev/video-bottom"};
  return {"/dev/video0", "/dev/video1"};
}

namespace {

// v4l2: the cameras' device paths (RobotSpec::CameraDevices): under /dev/
// (where the shim looks), shorter than the block's field, two distinct ones.
void readCameraDevices(const YamlReader& r, RobotSpec& rs) {
  RobotSpec::CameraDevices& d = rs.v4l2;
  d.path = defaultCameraDevices(rs.body);
  if (!r.has("v4l2")) return;
  if (rs.program != RobotSpec::Program::External)
    r.fail("v4l2", "the cameras as V4L2 devices are for a program of its own (program: {command: [...]} or "
                   "external)");
  if (!r.node()["v4l2"].IsMap()) {
    d.mode = r.choice("v4l2", "on", {"on", "off"}) == "on" ? RobotSpec::CameraDevices::Mode::On
                                                          : RobotSpec::CameraDevices::Mode::Off;
    return;
  }
  d.mode = RobotSpec::CameraDevices::Mode::On;
  const YamlReader m = r.map("v4l2");
  const char* keys[2] = {"top", "bottom"};
  for (int c = 0; c < 2; ++c) {
    d.path[c] = m.string(keys[c], d.path[c]);
    if (d.path[c].rfind("/dev/", 0) != 0 || d.path[c].size() <= 5 || d.path[c].size() >= 64)
      m.fail(keys[c], "a camera's device is a path under /dev/ of at most 63 characters (got '" + d.path[c] + "')");
  }
  if (d.path[0] == d.path[1]) m.fail("bottom", "the two cameras need two device paths (both are " + d.path[0] + ")");
  m.finish();
}

// One entry of robots:, its keys in this order (the first error wins).
RobotSpec readRobot(const YamlReader& r, const std::string& base_dir, RobotClaims& claims) {
  RobotSpec rs;
  rs.line = r.node().Mark().line + 1;
  readTeamPlayer(r, rs, claims);
  readNames(r, rs, claims);
  readPlacement(r, rs);
  readProgram(r, rs, base_dir);
  readLola(r, rs, claims);
  readCameraDevices(r, rs);
  readTimedLists(r, rs);
  checkBuiltinRelease(r, rs);
  r.finish();
  return rs;
}

void readRobots(const YamlReader& top, Scenario& sc) {
  RobotClaims claims;
  for (const YamlReader& r : top.list("robots")) sc.robots.push_back(readRobot(r, sc.base_dir, claims));
  if (sc.robots.empty()) top.fail("robots", "a scenario needs at least one robot");
  sc.world.tick_us = bodyCycleUs(sc.robots.front().body);
  // A V6 world gets the V6 body unless the file names a model.
  if (sc.robots.front().body == bridge::BodyInterface::Lola && !sc.model_named) sc.model_path = kV6Model;
}

}  // namespace

// Robots on top of one another (the field is not needed for this).
void checkRobotsApart(const Scenario& sc) {
  for (size_t i = 0; i < sc.robots.size(); ++i)
    for (size_t j = 0; j < i; ++j) {
      const double d = std::hypot(sc.robots[i].x - sc.robots[j].x, sc.robots[i].y - sc.robots[j].y);
      if (d < 2 * limits::kRobotRadius)
        throw ConfigError(sc.source, sc.robots[i].line, "robots[" + std::to_string(i) + "]",
                          "overlaps robots[" + std::to_string(j) + "] (centres " + std::to_string(d) +
                              " m apart; at least " + std::to_string(2 * limits::kRobotRadius) + " m needed)");
    }
}

// The blocks in file order of the documentation (docs/runner.md); the robots
// before team_comms and game, which may name them.
Scenario Scenario::parse(const std::string& text, const std::string& source_name) {
  const YAML::Node root = YamlReader::parse(text, source_name);
  return read(YamlReader(root, source_name), source_name);
}

Scenario Scenario::read(const YamlReader& top, const std::string& source_name) {
  Scenario sc;
  sc.source = source_name;
  readRun(top, sc);
  readNoise(top, sc.noise);
  readInertial(top, sc);
  readPhysics(top, sc.world);
  const std::optional<YamlReader> overview_reader = readCamera(top, sc.camera);
  readVision(top, sc.vision);
  readBall(top, sc);
  readRobots(top, sc);
  if (auto t = top.optionalMap("team_comms")) sc.team_comms = readTeamComms(*t);
  if (auto g = top.optionalMap("game")) sc.game = readGame(*g, static_cast<int>(sc.robots.size()));
  if (overview_reader && sc.camera.overview.robot >= static_cast<int>(sc.robots.size()))
    overview_reader->fail("robot", "no robot " + std::to_string(sc.camera.overview.robot) + " (the scenario has " +
                                       std::to_string(sc.robots.size()) + ")");
  checkRobotsApart(sc);
  top.finish();
  return sc;
}

void Scenario::checkAgainstField(const FieldConfig& f) const {
  auto fail = [&](int line, const std::string& what) {
    throw ConfigError(source, line, "", what + " (field " + f.source + ")");
  };
  const double r_post = f.goal.post_diameter / 2;
  const double post_y = f.goal.inner_width / 2 + r_post;  // as FieldGeometry.cpp builds them
  auto check = [&](int line, const std::string& what, double x, double y, double radius) {
    const double hx = f.carpetLength() / 2 - radius, hy = f.carpetWidth() / 2 - radius;
    if (std::fabs(x) > hx || std::fabs(y) > hy)
      fail(line, what + " at (" + std::to_string(x) + ", " + std::to_string(y) + ") m is off the carpet (|x| <= " +
                     std::to_string(hx) + ", |y| <= " + std::to_string(hy) + " m)");
    for (double sx : {-1.0, 1.0})
      for (double sy : {-1.0, 1.0}) {
        const double d = std::hypot(x - sx * f.length / 2, y - sy * post_y);
        if (d < radius + r_post)
          fail(line, what + " at (" + std::to_string(x) + ", " + std::to_string(y) + ") m is inside a goal post");
      }
  };
  for (size_t i = 0; i < robots.size(); ++i)
    check(robots[i].line, "robots[" + std::to_string(i) + "]", robots[i].x, robots[i].y, limits::kRobotRadius);
  if (ball) check(ball_line, "ball", ball->first, ball->second, f.ball.diameter / 2);
}

}  // namespace simswift::runner
