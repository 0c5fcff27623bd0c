#include "sim/runner/Scenario.hpp"

#include <fstream>
#include <set>
#include <sstream>

#include "agent/libagent/SharedNames.hpp"
#include "sim/world/YamlReader.hpp"

#ifndef SIMSWIFT_SOURCE_DIR
#define SIMSWIFT_SOURCE_DIR "."
#endif

namespace simswift::runner {

namespace al = agent::libagent;
using agent::program::Posture;
using agent::program::ScriptStep;

std::string sourceDir() { return SIMSWIFT_SOURCE_DIR; }

namespace {

std::string resolve(const std::string& base, const std::string& p) {
  if (p.empty() || p[0] == '/' || base.empty()) return p;
  return base + "/" + p;
}

ScriptStep readStep(const YamlReader& r) {
  ScriptStep s;
  s.t_s = r.number("t", Range::nonNegative());
  const bool has_joint = r.has("joint");
  const bool has_posture = r.has("posture");
  if (has_joint == has_posture) r.fail("a script step needs exactly one of 'joint' or 'posture'");
  if (has_joint) {
    const std::string name = r.string("joint");
    s.joint = agent::program::jointIndex(name);
    if (s.joint < 0) r.fail("joint", "unknown joint '" + name + "' (use NAO names, e.g. HeadYaw)");
    s.angle = static_cast<float>(r.number("angle"));
    s.duration_s = r.number("duration", 0.0, Range::nonNegative());
    if (r.has("stiffness")) s.stiffness = static_cast<float>(r.number("stiffness", Range::closed(-1, 1)));
  } else {
    const std::string p = r.choice("posture", "stand", {"stand", "crouch", "limp", "zero"});
    s.posture = *agent::program::parsePosture(p);
  }
  r.finish();
  return s;
}

}  // namespace

std::string Scenario::modelFile() const { return resolve(base_dir, model_path); }
std::string Scenario::fieldFile() const { return resolve(base_dir, field_path); }

Scenario Scenario::loadFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path + ": cannot open scenario file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str(), path);
}

Scenario Scenario::parse(const std::string& text, const std::string& source_name) {
  const YAML::Node root = YamlReader::parse(text, source_name);
  YamlReader top(root, source_name);
  Scenario sc;
  sc.source = source_name;
  sc.base_dir = top.string("base_dir", sourceDir());
  sc.model_path = top.string("model", "models/nao_v5.urdf");
  sc.field_path = top.string("field", "fields/spl_2017.yaml");
  sc.duration = top.number("duration", 10.0, Range::positive());
  sc.seed = static_cast<uint64_t>(top.integer("seed", 1, Range::nonNegative()));
  sc.watchdog_s = top.number("watchdog", 5.0, Range::positive());
  sc.attach_timeout_s = top.number("attach_timeout", 30.0, Range::positive());

  // noise: on/off, or a map of switches.
  if (top.has("noise")) {
    if (root["noise"].IsMap()) {
      YamlReader n = top.map("noise");
      sc.noise.on = n.boolean("enabled", true);
      sc.noise.gyro = n.boolean("gyro", true);
      sc.noise.accel = n.boolean("accel", true);
      sc.noise.angle = n.boolean("angle", true);
      sc.noise.fsr = n.boolean("fsr", true);
      sc.noise.sonar = n.boolean("sonar", true);
      sc.noise.encoder = n.boolean("encoder", true);
      n.finish();
    } else {
      sc.noise.on = top.boolean("noise");
    }
  }

  if (auto p = top.optionalMap("physics")) {
    sc.substeps = p->integer("substeps", sc.substeps, Range::closed(1, 100));
    sc.solver = p->choice("solver", sc.solver, {"exact", "quick"});
    sc.quick_iterations = p->integer("iterations", sc.quick_iterations, Range::closed(1, 1000));
    p->finish();
  }
  if (auto c = top.optionalMap("camera")) {
    sc.camera = c->boolean("enabled", false);
    c->finish();
  }
  if (auto b = top.optionalMap("ball")) {
    sc.ball = std::make_pair(b->number("x"), b->number("y"));
    b->finish();
  }

  std::set<int> suffixes;
  for (const YamlReader& r : top.list("robots")) {
    RobotSpec rs;
    rs.team = r.integer("team", Range::closed(0, al::kMaxTeams - 1));
    rs.player = r.integer("player", Range::closed(al::kMinPlayer, al::kMaxPlayer));
    if (!suffixes.insert(al::robotSuffix(rs.team, rs.player)).second)
      r.fail("player", "team " + std::to_string(rs.team) + " player " + std::to_string(rs.player) +
                           " appears twice");
    rs.x = r.number("x", 0.0);
    rs.y = r.number("y", 0.0);
    rs.theta = r.number("theta", 0.0);
    rs.posture = *agent::program::parsePosture(r.choice("posture", "stand", {"stand", "crouch", "limp", "zero"}));
    rs.program = r.choice("program", "builtin", {"builtin", "external"}) == "external"
                     ? RobotSpec::Program::External
                     : RobotSpec::Program::Builtin;
    if (r.has("script")) {
      if (rs.program == RobotSpec::Program::External)
        r.fail("script", "an external robot runs its own program; a script needs program: builtin");
      for (const YamlReader& s : r.list("script")) rs.script.push_back(readStep(s));
    }
    r.finish();
    sc.robots.push_back(std::move(rs));
  }
  if (sc.robots.empty()) top.fail("robots", "a scenario needs at least one robot");
  top.finish();
  return sc;
}

}  // namespace simswift::runner
