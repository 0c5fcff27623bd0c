#include "agent/program/RobotSetup.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "agent/behaviour/BehaviourModule.hpp"
#include "agent/behaviour/BehaviourYaml.hpp"
#include "common/config/Seed.hpp"
#include "common/libagent/SharedNames.hpp"
#include "agent/motion/ActionYaml.hpp"

namespace agent::program {

using common::config::Range;
using common::config::YamlReader;

namespace {

// Ankle damping gain (s) of the standing program's scripted posture; see
// ScriptedMotion.
constexpr float kPostureAnkleGyroGain = 0.05f;

constexpr double kMaxTime = 1e6;        // s: event times (11.6 days)
constexpr double kMaxJointAngle = 10;   // rad (the servos clamp to the joint's range)
constexpr double kMaxPosition = 50;     // m

}  // namespace

ProgramConfig composeProgram(const RobotSetup& s, std::unique_ptr<framework::MotionGenerator> motion,
                             const motion::MotionConfig& motion_config) {
  ProgramConfig pc;
  pc.motion = motion_config;
  pc.team = s.team;
  pc.player = s.player;
  pc.seed = s.seed;
  pc.motion_generator = std::move(motion);
  if (pc.motion_generator) return pc;
  if (s.behaviour) {
    // The behaviour plans with the walk's top speeds (calibrated so the
    // achieved speeds match them).
    behaviour::BehaviourModuleConfig bc;
    bc.behaviour = *s.behaviour;
    bc.team = s.team;
    bc.player = s.player;
    bc.walk.max_forward = pc.motion.walk.max_forward;
    bc.walk.max_left = pc.motion.walk.max_left;
    bc.walk.max_turn = pc.motion.walk.max_turn;
    pc.behaviour_config = bc;  // the module is built at start, for the body's lens
    if (s.start)  // m -> mm (the blackboard's)
      pc.localisation.known_start = blackboard::FieldPose{s.start->x * 1000.0, s.start->y * 1000.0, s.start->theta};
  } else if (!s.actions.empty()) {
    pc.actions = s.actions;
  } else {
    auto scripted = std::make_unique<ScriptedMotion>(s.posture, s.script);
    scripted->setAnkleGyroDamping(kPostureAnkleGyroGain);
    pc.motion_generator = std::move(scripted);
  }
  return pc;
}

ScriptStep readScriptStep(const YamlReader& r) {
  ScriptStep s;
  s.t_s = r.number("t", Range::closed(0, kMaxTime));
  const bool has_joint = r.has("joint");
  const bool has_posture = r.has("posture");
  if (has_joint == has_posture) {
    if (!has_joint) {  // neither: a misspelt one is named at its line
      r.checkMisspelling("joint");
      r.checkMisspelling("posture");
    }
    r.fail("a script step needs exactly one of 'joint' or 'posture'");
  }
  if (has_joint) {
    const std::string name = r.string("joint");
    s.joint = jointIndex(name);
    if (s.joint < 0) r.fail("joint", "unknown joint '" + name + "' (use NAO names, e.g. HeadYaw)");
    s.angle = static_cast<float>(r.number("angle", Range::closed(-kMaxJointAngle, kMaxJointAngle)));
    s.duration_s = r.number("duration", 0.0, Range::closed(0, kMaxTime));
    if (r.has("stiffness")) s.stiffness = static_cast<float>(r.number("stiffness", Range::closed(-1, 1)));
  } else {
    s.posture = *parsePosture(r.choice("posture", "stand", postureNames()));
  }
  r.finish();
  return s;
}

void readActions(const YamlReader& r, RobotSetup& s, const OutsideAction& outside) {
  if (!r.has("actions")) return;
  s.actions.clear();
  for (const YamlReader& a : r.list("actions")) {
    const double t = a.number("t", Range::closed(0, kMaxTime));
    if (outside && outside(a, t)) continue;
    s.actions.push_back(motion::readBodyAction(a, t));
  }
}

void readProgramKeys(const YamlReader& r, RobotSetup& s, const OutsideAction& outside) {
  if (r.has("script")) {
    s.script.clear();
    for (const YamlReader& st : r.list("script")) s.script.push_back(readScriptStep(st));
  }
  readActions(r, s, outside);
  if (r.has("behaviour")) s.behaviour = behaviour::readBehaviour(r, &s.behaviour_yaml);
}

void readRobotSetup(const YamlReader& r, RobotSetup& s) {
  s.team = r.integer("team", s.team, Range::closed(common::libagent::kMinTeamNumber, common::libagent::kMaxTeamNumber));
  s.player = r.integer("player", s.player, Range::closed(common::libagent::kMinPlayer, common::libagent::kMaxPlayer));
  // Up to 64 bits (the simulator derives robot seeds by mixing, DeriveSeed.hpp).
  s.seed = common::config::readSeed(r, "seed", s.seed);
  if (auto p = r.optionalMap("start")) {
    const Range pos = Range::closed(-kMaxPosition, kMaxPosition);
    RobotSetup::StartPose f;
    f.x = p->number("x", pos);  // m
    f.y = p->number("y", pos);
    f.theta = p->number("theta", f.theta, Range::closed(-2 * M_PI, 2 * M_PI));
    p->finish();
    s.start = f;
  }
  s.posture = *parsePosture(r.choice("posture", postureName(s.posture), postureNames()));
  readProgramKeys(r, s);
  r.finish();
}

RobotSetup readRobotSetup(const std::string& path) {
  RobotSetup s;
  const YAML::Node root = YamlReader::parseFile(path);
  if (!root.IsMap() && !root.IsNull()) YamlReader(root, path).fail("a robot program's config is a map of keys");
  readRobotSetup(YamlReader(root.IsNull() ? YAML::Node(YAML::NodeType::Map) : root, path), s);
  return s;
}

std::string robotSetupYaml(const RobotSetup& s) {
  std::ostringstream o;
  char buf[256];
  o << "# A robot program's setup, written by simswift (agent/program/RobotSetup.hpp).\n";
  o << "team: " << s.team << "\nplayer: " << s.player << "\nseed: " << s.seed << "\n";
  if (s.start) {
    // %.17g: reads back to the same double.
    std::snprintf(buf, sizeof buf, "start: {x: %.17g, y: %.17g, theta: %.17g}\n", s.start->x, s.start->y,
                  s.start->theta);
    o << buf;
  }
  if (!s.behaviour_yaml.empty()) o << "behaviour: " << s.behaviour_yaml << "\n";
  if (!s.actions.empty()) {
    o << "actions:\n";
    for (const motion::ActionStep& a : s.actions) o << "  - " << motion::bodyActionYaml(a) << "\n";
  }
  o << "posture: " << postureName(s.posture) << "\n";
  if (!s.script.empty()) {
    o << "script:\n";
    for (const ScriptStep& st : s.script) {
      if (st.joint < 0) {
        std::snprintf(buf, sizeof buf, "  - {t: %.17g, posture: %s}\n", st.t_s, postureName(st.posture));
        o << buf;
        continue;
      }
      std::snprintf(buf, sizeof buf, "  - {t: %.17g, joint: %s, angle: %.9g, duration: %.17g", st.t_s,
                    common::libagent::Joints::kNames[st.joint], st.angle, st.duration_s);
      o << buf;
      if (st.stiffness >= -1) {
        std::snprintf(buf, sizeof buf, ", stiffness: %.9g", st.stiffness);
        o << buf;
      }
      o << "}\n";
    }
  }
  return o.str();
}

}  // namespace agent::program
