#include "app/experiment/Experiment.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "common/config/Seed.hpp"
#include "common/libagent/SharedNames.hpp"
#include "common/nao/NaoFacts.hpp"
#include "common/random/DeriveSeed.hpp"
#include "sim/runner/Bodies.hpp"
#include "sim/vision/VisionConfig.hpp"
#include "sim/world/ConfigError.hpp"

namespace simswift::experiment {

namespace al = common::libagent;

namespace {

// Two robots' start positions closer than this (m, torso to torso) stand on
// each other: a NAO's footprint is about 0.2 x 0.3 m.
constexpr double kMinRobotSeparation = 0.30;

// An opaque map as one line of YAML (deterministic: yaml-cpp keeps the order).
std::string flow(const YAML::Node& n) {
  YAML::Emitter e;
  e << YAML::Flow << n;
  return e.c_str();
}

}  // namespace

int Experiment::maxRobots() const {
  size_t n = 0;
  for (const Setup& s : setups) n = std::max(n, s.robots.size());
  return static_cast<int>(n);
}

Experiment Experiment::loadFile(const std::string& path) {
  return parse(YamlReader::readFile(path, "experiment file"), path);
}

namespace {

// The file's header: name, paths, noise, physics, field, seed, time limit
// and trials. `field`: as parseTree's.
void readHeader(const YamlReader& top, const std::string& source_name, const FieldConfig* field, Experiment& e) {
  e.source = source_name;
  e.name = top.string("name");
  if (e.name.empty() || e.name.find_first_of("/\\ \t") != std::string::npos)
    top.fail("name", "must be a non-empty word without spaces or slashes (it names the results folder)");
  e.base.source = source_name;
  // Relative paths resolve as a scenario's do: this file's folder, then the data folders.
  e.base.base_dir = top.string("base_dir", std::filesystem::path(source_name).parent_path().string());
  e.base.model_path = top.string("model", e.base.model_path);
  e.base.field_path = top.string("field", e.base.field_path);
  runner::readNoise(top, e.base.noise);  // the scenario's noise: (on/off or a map)
  runner::readPhysics(top, e.base.world);
  (void)top.has("sweep");  // Experiment::parse's
  try {
    e.field = field ? *field : FieldConfig::loadYaml(e.base.fieldFile());
  } catch (const ConfigError& err) {
    top.fail("field", std::string("cannot load the field: ") + err.what());
  }
  e.seed = common::config::readSeed(top, "seed");  // all 64 bits, exact (not a YAML number)
  e.time_limit = top.number("time_limit", Range::positive());
  if (e.time_limit > 3600) top.fail("time_limit", "must be <= 3600 s (got " + std::to_string(e.time_limit) + ")");
  e.trials_per_position = top.integer("trials_per_position", Range::closed(1, 10000));
}

// The trial's rules: start:, found:, fallen:, tracks: and the vision: they need.
void readRules(const YamlReader& top, const YAML::Node& root, Experiment& e) {
  if (auto st = top.optionalMap("start")) {
    e.start.penalised = st->number("penalised", e.start.penalised, Range::closed(0.05, 60));
    st->finish();
  }
  const double ball_radius = e.field.ball.diameter / 2;
  if (auto f = top.optionalMap("found")) {
    e.found.distance = f->number("distance", e.found.distance, Range::positive());
    if (e.found.distance < ball_radius)
      f->fail("distance", "must be >= the ball radius " + std::to_string(ball_radius) + " m (got " +
                              std::to_string(e.found.distance) + ")");
    e.found.sees = f->boolean("sees", true);
    e.found.seen_frames = f->integer("seen_frames", 1, Range::closed(1, 300));  // 300 frames: 10 s
    if (!e.found.sees && e.found.seen_frames != 1)
      f->fail("seen_frames", "counts frames the robot saw the ball: it needs sees: true");
    f->finish();
  }
  if (auto f = top.optionalMap("fallen")) {
    e.fallen.sideline_after = f->number("sideline_after", e.fallen.sideline_after, Range::positive());
    f->finish();
  }
  if (auto t = top.optionalMap("tracks")) {
    e.track_every = t->number("every", e.track_every, Range::closed(0.01, 60));
    t->finish();
  }
  if (top.has("vision")) {
    // The scenario's vision: block, read (and checked) by the vision
    // oracle's own reader; every trial's scenario gets it.
    if (!root["vision"].IsMap()) top.fail("vision", "must be a map (the scenario's vision: block)");
    e.vision_yaml = flow(root["vision"]);
    e.base.vision = vision::readVisionConfig(top.map("vision"), e.base.vision);
  }
  if (e.found.sees && (!e.base.vision.enabled || !e.base.vision[vision::Feature::Ball].enabled)) {
    const std::string why = "the found rule needs the robots' ball detections, but the vision: block turns them "
                            "off (use found: {sees: false}, or enable vision and its ball detector)";
    if (top.has("found") && root["found"]["sees"].IsDefined()) top.map("found").fail("sees", why);
    top.fail("vision", why);
  }
}

// Everything must lie on the carpet (m, field frame); `margin` keeps the
// object's own size on it.
void checkOnCarpet(const FieldConfig& field, const YamlReader& r, double x, double y, double margin,
                   const std::string& what) {
  const double half_l = field.carpetLength() / 2, half_w = field.carpetWidth() / 2;
  if (std::abs(x) > half_l - margin || std::abs(y) > half_w - margin) {
    std::ostringstream m;
    m << what << " (" << x << ", " << y << ") m is off the carpet (|x| <= " << half_l - margin
      << ", |y| <= " << half_w - margin << " m)";
    r.fail(std::abs(x) > half_l - margin ? "x" : "y", m.str());
  }
}

void readBalls(const YamlReader& top, Experiment& e) {
  const double ball_radius = e.field.ball.diameter / 2;
  std::set<int> numbers;
  for (const YamlReader& b : top.list("balls")) {
    BallPosition p;
    p.number = b.integer("position", Range::closed(1, 1000));
    if (!numbers.insert(p.number).second) b.fail("position", "ball position " + std::to_string(p.number) + " appears twice");
    p.x = b.number("x");
    p.y = b.number("y");
    p.note = b.string("note", "");
    checkOnCarpet(e.field, b, p.x, p.y, ball_radius, "the ball");
    b.finish();
    e.balls.push_back(p);
  }
  if (e.balls.empty()) top.fail("balls", "an experiment needs at least one ball position");
}

// A setup's or robot's program. `external` (a program started by hand)
// cannot be restarted for each trial: refused. any_body: a setup's default
// program, whose placeholders its robots' bodies decide.
runner::LaunchSpec readLaunch(const YamlReader& m, const std::string& base_dir, bool any_body) {
  runner::RobotSpec tmp;
  runner::readProgram(m, tmp, base_dir, any_body);
  if (tmp.program == runner::RobotSpec::Program::External && !tmp.launch.launched())
    m.fail("program", "an experiment starts every trial's programs itself: builtin or {command: [...]}");
  return tmp.launch;
}

// What a setup gives its robots unless they say otherwise.
struct SetupDefaults {
  bool has_behaviour = false;
  std::string behaviour;
  ConfigPlace behaviour_where;
  std::string config;  // one line of YAML, empty: none
  runner::LaunchSpec launch;
};

SetupDefaults readSetupDefaults(const YamlReader& s, const Experiment& e) {
  SetupDefaults d;
  d.has_behaviour = s.has("behaviour");
  d.behaviour = d.has_behaviour ? s.choice("behaviour", programs::kScriptBehaviour, programs::behaviourNames()) : "";
  d.behaviour_where = d.has_behaviour ? s.place("behaviour") : ConfigPlace{};
  if (s.has("config")) {
    if (!s.node()["config"].IsMap()) s.fail("config", "must be a map of behaviour overrides");
    (void)s.map("config").keys();  // a list or map as a key: refused here, at its line
    d.config = flow(s.node()["config"]);
  }
  d.launch = readLaunch(s, e.base.base_dir, true);
  return d;
}

// The robot's behaviour, its config overrides and its program.
void readRobotProgram(const YamlReader& r, const YamlReader& s, const SetupDefaults& d, const Experiment& e,
                      ExperimentRobot& rob) {
  if (r.has("behaviour")) {
    rob.behaviour = r.choice("behaviour", programs::kScriptBehaviour, programs::behaviourNames());
    rob.behaviour_where = r.place("behaviour");
  } else if (d.has_behaviour) {
    rob.behaviour = d.behaviour;
    rob.behaviour_where = d.behaviour_where;
  } else {
    r.checkMisspelling("behaviour");
    s.checkMisspelling("behaviour");  // the setup's default, misspelt
    r.fail("behaviour", "missing: give the robot (or its setup) a behaviour: " + programs::behaviourNamesText());
  }
  rob.config_yaml = d.config;
  if (r.has("config")) {
    if (!r.node()["config"].IsMap()) r.fail("config", "must be a map of behaviour overrides");
    // The robot's overrides replace the setup's key by key.
    YAML::Node merged = d.config.empty() ? YAML::Node(YAML::NodeType::Map) : YAML::Load(d.config);
    const YamlReader overrides = r.map("config");
    for (const YamlReader::Key& k : overrides.keys()) merged[k.name] = overrides.node()[k.name];
    rob.config_yaml = flow(merged);
  }
  rob.launch = r.has("program") ? readLaunch(r, e.base.base_dir, false) : d.launch;
}

// One robot of setup `setup` (its robots so far), `s` its setup's reader;
// `players`: the setup's (team, player) pairs so far.
ExperimentRobot readRobot(const YamlReader& r, const YamlReader& s, const SetupDefaults& d, const Setup& setup,
                          const Experiment& e, std::set<std::pair<int, int>>& players) {
  ExperimentRobot rob;
  rob.team = r.integer("team", Range::closed(al::kMinTeamNumber, al::kMaxTeamNumber));
  rob.player = r.integer("player", Range::closed(al::kMinPlayer, al::kMaxPlayer));
  if (!players.insert({rob.team, rob.player}).second)
    r.fail("player", "team " + std::to_string(rob.team) + " player " + std::to_string(rob.player) +
                         " appears twice in setup '" + setup.name + "'");
  rob.x = r.number("x");
  rob.y = r.number("y");
  rob.theta = r.number("theta", Range::closed(-2 * M_PI, 2 * M_PI));
  checkOnCarpet(e.field, r, rob.x, rob.y, common::nao::kFootprintRadius / 1000, "the robot");  // m
  readRobotProgram(r, s, d, e, rob);
  if (const std::optional<YamlReader> l = r.optionalMap("lola")) {
    l->finish();  // no keys: the socket is the trial's own
    rob.v6 = true;
  }
  if (!setup.robots.empty() && setup.robots.front().v6 != rob.v6)
    r.fail(rob.v6 ? "lola" : "team", "every robot of a setup ticks alike: its first robot is a " +
                                          std::string(setup.robots.front().v6 ? "NAO V6 (lola, 12 ms)"
                                                                              : "NAO V5 (libagent, 10 ms)"));
  if (rob.isScript()) {
    if (!r.has("actions"))
      r.missing("actions", "missing: a script robot needs an actions: list (as in a scenario)");
    runner::readActions(r, rob.script);
  } else if (r.has("actions")) {
    r.fail("actions", "only a script robot takes actions (this one is " +
                          rob.behaviour + ")");
  }
  r.finish();
  // Robots standing on each other.
  for (const ExperimentRobot& o : setup.robots)
    if (std::hypot(o.x - rob.x, o.y - rob.y) < kMinRobotSeparation) {
      std::ostringstream m;
      m << "stands on player " << o.player << " (" << std::hypot(o.x - rob.x, o.y - rob.y)
        << " m apart; robots need >= " << kMinRobotSeparation << " m)";
      r.fail("x", m.str());
    }
  return rob;
}

// The setup's robots together: present, off the balls, one match.
void checkSetupRobots(const YamlReader& s, const Setup& setup, const Experiment& e) {
  if (setup.robots.empty()) s.fail("robots", "a setup needs at least one robot");
  const double ball_radius = e.field.ball.diameter / 2;
  // A ball inside a robot's start footprint would be pushed away at once.
  for (const ExperimentRobot& rob : setup.robots)
    for (const BallPosition& b : e.balls)
      if (std::hypot(b.x - rob.x, b.y - rob.y) < kMinRobotSeparation / 2 + ball_radius)
        s.fail("robots", "player " + std::to_string(rob.player) + " starts on ball position " +
                             std::to_string(b.number));
  std::set<int> teams;
  for (const ExperimentRobot& rob : setup.robots) teams.insert(rob.team);
  if (teams.size() > 2) s.fail("robots", "a setup is one match: at most two team numbers");
}

void readSetups(const YamlReader& top, Experiment& e) {
  std::set<std::string> setup_names;
  for (const YamlReader& s : top.list("setups")) {
    Setup setup;
    setup.name = s.string("name");
    if (setup.name.empty() || setup.name.find_first_of(",\"\n/ ") != std::string::npos)
      s.fail("name", "must be a non-empty word without spaces, commas, quotes or slashes");
    if (!setup_names.insert(setup.name).second) s.fail("name", "setup '" + setup.name + "' appears twice");
    setup.thesis_table = s.choice("thesis_table", "", {"", "5.3", "5.4", "5.5", "5.6", "5.7", "5.8"});
    const SetupDefaults d = readSetupDefaults(s, e);
    std::set<std::pair<int, int>> players;
    for (const YamlReader& r : s.list("robots")) setup.robots.push_back(readRobot(r, s, d, setup, e, players));
    checkSetupRobots(s, setup, e);
    s.finish();
    e.setups.push_back(std::move(setup));
  }
  if (e.setups.empty()) top.fail("setups", "an experiment needs at least one setup");
}

// The scenario's team_comms: and game: blocks, by its readers. The trial
// owns the game's start (penalised at the start poses, then PLAYING).
void readMatch(const YamlReader& top, Experiment& e) {
  if (auto t = top.optionalMap("team_comms")) e.base.team_comms = runner::readTeamComms(*t);
  if (auto g = top.optionalMap("game")) {
    for (const char* key : {"state", "timeline", "penalties", "on_unpenalise", "udp", "address", "port", "return_port"})
      if (g->has(key))
        g->fail(key, "set by each trial (penalised at the start poses, then PLAYING; no GameController packets "
                     "from parallel trials): an experiment's game: takes kickoff_team, half_duration, first_half");
    e.base.game = runner::readGame(*g, e.maxRobots());
  }
}

// The experiment of one tree: the file's own, or the file's with swept
// values set in (Sweep.hpp). Never looks at sweep: beyond its name. `field`:
// the field already loaded for the file's own tree (a sweep cannot change
// it), else it is loaded here.
Experiment parseTree(const YAML::Node& root, const std::string& source_name, const FieldConfig* field = nullptr) {
  if (!root.IsMap()) throw ConfigError(source_name, 1, "", "an experiment file is a map (name:, seed:, balls:, ...)");
  YamlReader top(root, source_name);
  Experiment e;
  readHeader(top, source_name, field, e);
  readRules(top, root, e);
  readBalls(top, e);
  readSetups(top, e);
  readMatch(top, e);
  top.finish();
  if (e.countTrials() > kMaxTrials)
    top.fail("trials_per_position", std::to_string(e.setups.size()) + " setups x " + std::to_string(e.balls.size()) +
                                        " positions x " + std::to_string(e.trials_per_position) + " = " +
                                        std::to_string(e.countTrials()) + " trials is more than " +
                                        std::to_string(kMaxTrials));
  return e;
}

}  // namespace

Experiment Experiment::parse(const std::string& text, const std::string& source_name) {
  const YAML::Node root = YamlReader::parse(text, source_name);
  Experiment e = parseTree(root, source_name);
  e.text = text;
  if (!root["sweep"]) return e;
  const YamlReader top(root, source_name);
  e.sweep = readSweep(top);
  for (const auto& kv : root)
    if (kv.first.IsScalar() && kv.first.Scalar() == "sweep")
      e.sweep_line = kv.first.Mark().is_null() ? 1 : kv.first.Mark().line + 1;
  // Every check below reads the whole tree (all nodes but the sweep list's):
  // refused first if that is too much. With one path a cell is a value
  // alone, checked once.
  const int n = sweepCells(e.sweep);
  const bool one_axis = e.sweep.size() == 1;
  long long checks = one_axis ? 0 : n;
  for (const SweepAxis& a : e.sweep) checks += static_cast<long long>(a.values.size());
  const long long nodes = static_cast<long long>(expandedNodes(root, kMaxConfigNodes)) -
                          static_cast<long long>(expandedNodes(root["sweep"], kMaxConfigNodes));
  if (checks * nodes > kMaxSweepNodes) {
    const std::string what = one_axis ? "each value" : "each value alone, then each of the " + std::to_string(n) + " cells";
    throw ConfigError(source_name, e.sweep_line, "sweep", std::to_string(checks) +
                      " checks (" + what + ") of a file of " + std::to_string(nodes) + " YAML nodes is more than " +
                      std::to_string(kMaxSweepNodes) + " nodes to read; sweep fewer values or shorten the file");
  }
  // Each value alone on the base, so an error names the value's line; then
  // every cell (values that are fine alone may clash together). Values are
  // set into the file's own tree and taken back after each check.
  SweepTree tree(root);
  for (SweepAxis& a : e.sweep)
    for (size_t v = 0; v < a.values.size(); ++v) {
      tree.apply(a, static_cast<int>(v), source_name);
      try {
        a.values[v].alone = std::make_shared<const Experiment>(parseTree(root, source_name, &e.field));
      } catch (const ConfigError& err) {
        throw blameValue(source_name, a, static_cast<int>(v), err.what());
      }
      tree.restore();
    }
  for (int c = 0; c < n; ++c) {
    if (one_axis) {
      e.cells.push_back(e.sweep[0].values[c].alone);
      continue;
    }
    const std::vector<int> choice = sweepChoice(e.sweep, c);
    for (size_t k = 0; k < e.sweep.size(); ++k) tree.apply(e.sweep[k], choice[k], source_name);
    try {
      e.cells.push_back(std::make_shared<const Experiment>(parseTree(root, source_name, &e.field)));
    } catch (const ConfigError& err) {
      throw blameCell(source_name, e.sweep_line, e.sweep, c, err.what());
    }
    tree.restore();
  }
  if (e.countTrials() > kMaxTrials)
    throw ConfigError(source_name, e.sweep_line, "sweep", std::to_string(e.numCells()) +
                      " cells x " + std::to_string(e.countTrialsPerCell()) + " trials = " +
                      std::to_string(e.countTrials()) + " trials is more than " + std::to_string(kMaxTrials));
  return e;
}

TrialSpec trialSpec(const Experiment& e, int index) {
  TrialSpec t;
  t.index = index;
  t.cell = index / e.trialsPerCell();
  const int within = index % e.trialsPerCell();  // = index without a sweep
  const int per_setup = static_cast<int>(e.balls.size()) * e.trials_per_position;
  t.setup = within / per_setup;
  t.ball = (within % per_setup) / e.trials_per_position;
  t.repeat = within % e.trials_per_position;
  // Stateless: a pure function of (experiment seed, trial index), the same
  // in every cell (common random numbers: cells differ by their settings only).
  // Reduced to 31 bits (mod 2^31 - 1): trial seeds are published in
  // results.csv and the docs as 31-bit numbers, so they must not move.
  using common::random::deriveSeed;
  t.seed = deriveSeed(deriveSeed(e.seed, common::random::seed_tag::kTrial), static_cast<uint64_t>(within)) %
           2147483647ull;
  return t;
}

runner::TeamColour teamColour(const Setup& s, int spl_team) {
  return s.robots.empty() || s.robots.front().team == spl_team ? runner::TeamColour::Blue : runner::TeamColour::Red;
}

runner::Scenario trialScenario(const Experiment& top, const TrialSpec& t) {
  const Experiment& e = top.cell(t.cell);
  runner::Scenario sc = e.base;
  sc.source = e.source + " (trial " + std::to_string(t.index) + ")";
  sc.seed = t.seed;
  const Setup& s = e.setups[t.setup];
  sc.world.tick_us = setupTickUs(s);
  const double tick_s = static_cast<double>(sc.world.tick_us) * 1e-6;
  sc.duration = static_cast<double>(playTick(e, sc.world.tick_us)) * tick_s + e.time_limit;
  const BallPosition& b = e.balls[t.ball];
  sc.ball = std::make_pair(b.x, b.y);
  // A V6 setup gets the V6 body unless the file names a model.
  const bool v6 = !s.robots.empty() && s.robots.front().v6;
  if (v6 && !sc.model_named) sc.model_path = runner::kV6Model;
  for (const ExperimentRobot& r : s.robots) {
    runner::RobotSpec rs;
    if (r.isScript()) rs = r.script;
    rs.team = r.team;
    rs.colour = teamColour(s, r.team);
    rs.player = r.player;
    rs.x = r.x;
    rs.y = r.y;
    rs.theta = r.theta;
    rs.posture = common::nao::Posture::Stand;
    rs.program = r.launch.launched() ? runner::RobotSpec::Program::External : runner::RobotSpec::Program::Builtin;
    rs.launch = r.launch;
    if (r.v6) rs.body = bridge::BodyInterface::Lola;  // lola_socket empty: the process's own (Bodies.hpp)
    sc.robots.push_back(std::move(rs));
  }
  // findballexp's start (thesis §3.2.6, §5.1): every robot penalised at its
  // start pose (Runner::start() applies the t = 0 penalties; the trial puts
  // the robots back on their poses before the first tick, and they stay
  // there when unpenalised), then PLAYING and unpenalised together.
  using game::GameConfig;
  GameConfig& g = sc.game;
  g = GameConfig{};
  g.kickoff_team = e.base.game.kickoff_team;  // the experiment's game: (defaults without one)
  g.half_duration_s = e.base.game.half_duration_s;
  g.first_half = e.base.game.first_half;
  g.initial_state = common::libagent::GameStateValue::Initial;
  g.on_unpenalise = GameConfig::Return::Sideline;  // stays where it stands
  const double play_s = static_cast<double>(playTick(e, sc.world.tick_us)) * tick_s;
  g.timeline.push_back({play_s, common::libagent::GameStateValue::Playing});
  const int n = static_cast<int>(s.robots.size());
  for (int i = 0; i < n; ++i) g.penalties.push_back({0.0, i, common::libagent::Penalty::Manual, -1.0});
  for (int i = 0; i < n; ++i) g.penalties.push_back({play_s, i, common::libagent::Penalty::None, -1.0});
  return sc;
}

int64_t playTick(const Experiment& e, int64_t tick_us) {
  return std::max<int64_t>(1, common::nao::ticksIn(e.start.penalised, tick_us));
}

int64_t setupTickUs(const Setup& s) {
  return runner::bodyCycleUs(!s.robots.empty() && s.robots.front().v6 ? bridge::BodyInterface::Lola
                                                                     : bridge::BodyInterface::Libagent);
}

}  // namespace simswift::experiment

namespace simswift::experiment {

bool foundBy(const FoundSpec& f, int64_t sighting_frame, double sighting_distance_m, int consecutive,
             int64_t last_frame, double true_distance_m) {
  // Inclusive, as the thesis's "within 300mm (inclusive)"; 1 um slack for rounding.
  const double slack = 1e-6;
  if (!f.sees) return true_distance_m <= f.distance + slack;
  return sighting_frame >= 0 && sighting_frame == last_frame && consecutive >= f.seen_frames &&
         sighting_distance_m <= f.distance + slack;
}

}  // namespace simswift::experiment
