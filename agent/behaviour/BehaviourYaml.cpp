#include "agent/behaviour/BehaviourYaml.hpp"

#include "agent/behaviour/SearchPayload.hpp"

namespace agent::behaviour {

namespace ab = agent::behaviour;
using common::config::Range;
using common::config::YamlReader;

namespace {

// Overrides in place: each key defaults to the field's current value.
void num(const YamlReader& r, const char* key, double& v, const Range& range = Range::any()) {
  v = r.number(key, v, range);
}
void flag(const YamlReader& r, const char* key, bool& v) { v = r.boolean(key, v); }

void readField(const YamlReader& r, ab::FieldGeometry& f) {
  num(r, "length", f.length, Range::closed(1000, 20000));
  num(r, "width", f.width, Range::closed(1000, 20000));
  num(r, "goal_post_y", f.goal_post_y, Range::closed(0, 5000));
  num(r, "goal_post_radius", f.goal_post_radius, Range::closed(0, 500));
  r.finish();
}

void readGrid(const YamlReader& r, ab::GridConfig& g) {
  g.columns = r.integer("columns", g.columns, Range::closed(1, 20));
  g.rows = r.integer("rows", g.rows, Range::closed(1, 20));
  if (g.columns * g.rows > ab::SearchPayload::kMaxSegments)
    r.fail("rows", "columns x rows must fit the team packet (at most " +
                       std::to_string(ab::SearchPayload::kMaxSegments) + " segments)");
  flag(r, "derive_from_detection", g.derive_from_detection);
  num(r, "reliable_detection_distance", g.reliable_detection_distance, Range::closed(100, 20000));
  num(r, "detection_margin", g.detection_margin, Range::closed(0, 5000));
  if (g.detection_margin >= g.reliable_detection_distance)
    r.fail("detection_margin", "must be less than reliable_detection_distance");
  r.finish();
}

void readDistribution(const YamlReader& r, ab::DistributionConfig& d) {
  num(r, "ball_pos_rate", d.ball_pos_rate, Range::closed(0, 1000));
  num(r, "entropy_rate", d.entropy_rate, Range::closed(0, 100));
  num(r, "robot_pos_rate", d.robot_pos_rate, Range::closed(0, 100));
  num(r, "flip_min_confidence", d.flip_min_confidence, Range::closed(0, 1));
  r.finish();
}

void readStrategy(const YamlReader& r, ab::StrategyConfig& s) {
  flag(r, "distributed", s.distributed);
  num(r, "min_travel_time", s.min_travel_time, Range::positive());
  num(r, "teammate_timeout", s.teammate_timeout, Range::positive());
  num(r, "face_distance", s.face_distance, Range::nonNegative());
  flag(r, "exclusive_segments", s.exclusive_segments);
  r.finish();
}

void readSearch(const YamlReader& r, ab::SearchBehaviourConfig& s) {
  num(r, "arrive_distance", s.arrive_distance, Range::closed(10, 5000));
  flag(r, "scan_at_point", s.scan_at_point);
  flag(r, "spin_at_point", s.spin_at_point);
  flag(r, "scan_while_walking", s.scan_while_walking);
  num(r, "switch_hysteresis", s.switch_hysteresis, Range::atLeast(1));
  if (r.has("points_2016")) {
    s.points_2016.clear();
    for (const YamlReader& p : r.list("points_2016")) {
      s.points_2016.push_back({p.number("x", Range::closed(-10000, 10000)),
                               p.number("y", Range::closed(-10000, 10000))});
      p.finish();
    }
    if (s.points_2016.empty()) r.fail("points_2016", "needs at least one point ({x: mm, y: mm})");
  }
  r.finish();
}

void readSearch2016(const YamlReader& r, ab::Search2016Config& s) {
  const std::string style = r.choice("style", s.style == ab::Search2016Style::ERA ? "era" : "stop_scan_spin",
                                     {"era", "stop_scan_spin"});
  s.style = style == "era" ? ab::Search2016Style::ERA : ab::Search2016Style::STOP_SCAN_SPIN;
  const std::string head = r.choice("head", s.head == ab::Search2016Head::BALL_ESTIMATE ? "ball_estimate" : "scan",
                                    {"ball_estimate", "scan"});
  s.head = head == "ball_estimate" ? ab::Search2016Head::BALL_ESTIMATE : ab::Search2016Head::SCAN;
  num(r, "pass_distance", s.pass_distance, Range::closed(10, 5000));
  num(r, "head_near_pitch", s.head_near_pitch, Range::closed(-0.67, 0.51));
  num(r, "head_far_pitch", s.head_far_pitch, Range::closed(-0.67, 0.51));
  num(r, "head_near_distance", s.head_near_distance, Range::nonNegative());
  num(r, "head_yaw_speed", s.head_yaw_speed, Range::closed(0.01, 8.27));
  num(r, "head_pitch_speed", s.head_pitch_speed, Range::closed(0.01, 8.27));
  r.finish();
}

void readSkills(const YamlReader& r, ab::SkillConfig& k) {
  num(r, "walk_gain", k.walk_gain, Range::positive());
  num(r, "turn_gain", k.turn_gain, Range::positive());
  num(r, "face_target_distance", k.face_target_distance, Range::nonNegative());
  num(r, "final_angle_tolerance", k.final_angle_tolerance, Range::closed(0, 3.15));
  num(r, "translate_max_heading_error", k.translate_max_heading_error, Range::closed(0, 3.15));
  num(r, "robot_radius", k.robot_radius, Range::closed(0, 1000));
  num(r, "avoid_distance", k.avoid_distance, Range::nonNegative());
  num(r, "avoid_gain", k.avoid_gain, Range::nonNegative());
  num(r, "obstacle_timeout", k.obstacle_timeout, Range::nonNegative());
  num(r, "keep_out_distance", k.keep_out_distance, Range::closed(0, 3000));
  num(r, "blocked_arrive_distance", k.blocked_arrive_distance, Range::closed(0, 5000));
  flag(r, "sonar_avoid", k.sonar_avoid);
  num(r, "sonar_near_distance", k.sonar_near_distance, Range::closed(0, 2550));
  num(r, "sonar_min_frames", k.sonar_min_frames, Range::closed(0, 100));
  num(r, "sonar_hold_frames", k.sonar_hold_frames, Range::closed(0, 100));
  num(r, "sonar_obstacle_distance", k.sonar_obstacle_distance, Range::closed(0, 2000));
  num(r, "sonar_obstacle_angle", k.sonar_obstacle_angle, Range::closed(0, 1.5708));
  num(r, "sonar_back_off_speed", k.sonar_back_off_speed, Range::closed(0, 500));
  flag(r, "keep_right", k.keep_right);
  num(r, "pass_lookahead", k.pass_lookahead, Range::closed(0, 5000));
  num(r, "pass_clearance", k.pass_clearance, Range::closed(0, 2000));
  num(r, "pass_max_steer", k.pass_max_steer, Range::closed(0, 1.5708));
  if (k.keep_right && k.pass_max_steer >= k.translate_max_heading_error)
    r.fail("pass_max_steer",
           "must be less than translate_max_heading_error, or a robot passing a teammate stops to turn");
  num(r, "scan_yaw", k.scan_yaw, Range::closed(0, 2.0857));
  num(r, "scan_speed", k.scan_speed, Range::closed(0.01, 8.27));
  num(r, "scan_pitch", k.scan_pitch, Range::closed(-0.67, 0.51));
  num(r, "head_yaw_limit", k.head_yaw_limit, Range::closed(0, 2.0857));
  num(r, "head_speed_limit", k.head_speed_limit, Range::closed(0.01, 8.27));
  if (r.has("camera_hfov")) k.camera_hfov = r.number("camera_hfov", Range::closed(0.1, 3.0));  // else the body's
  num(r, "scan_lead", k.scan_lead, Range::closed(1, 10));
  num(r, "head_pitch_speed", k.head_pitch_speed, Range::closed(0.01, 8.27));
  num(r, "head_height", k.head_height, Range::closed(100, 1000));
  num(r, "look_pitch_offset", k.look_pitch_offset, Range::closed(-1, 1));
  num(r, "look_max_pitch", k.look_max_pitch, Range::closed(0, 0.51));
  num(r, "look_yaw_speed", k.look_yaw_speed, Range::closed(0.01, 8.27));
  num(r, "look_pitch_speed", k.look_pitch_speed, Range::closed(0.01, 8.27));
  num(r, "spin_speed", k.spin_speed, Range::closed(0.01, 5));
  num(r, "spin_angle", k.spin_angle, Range::closed(0, 20));
  num(r, "approach_distance", k.approach_distance, Range::closed(50, 2000));
  num(r, "approach_tolerance", k.approach_tolerance, Range::closed(1, 1000));
  num(r, "kick_angle_tolerance", k.kick_angle_tolerance, Range::closed(0.01, 3.15));
  num(r, "kick_duration", k.kick_duration, Range::closed(0.1, 10));
  num(r, "kick_power", k.kick_power, Range::closed(0, 1));
  num(r, "ball_lost_time", k.ball_lost_time, Range::nonNegative());
  num(r, "team_ball_max_age", k.team_ball_max_age, Range::nonNegative());
  flag(r, "team_roles", k.team_roles);
  num(r, "role_margin", k.role_margin, Range::closed(0, 5000));
  num(r, "support_distance", k.support_distance, Range::closed(200, 5000));
  if (r.has("kick_target")) {
    const std::vector<double> t = r.numbers("kick_target", 2);
    k.kick_target = {t[0], t[1]};
  }
  r.finish();
}

}  // namespace

std::optional<ab::BehaviourConfig> readBehaviour(const YamlReader& robot, std::string* yaml) {
  ab::BehaviourConfig c;
  if (yaml) {
    YAML::Emitter e;
    e << YAML::Flow << robot.node()["behaviour"];
    *yaml = e.c_str();
  }
  std::string kind;
  std::optional<YamlReader> m;
  if (robot.node()["behaviour"].IsMap()) {
    m = robot.map("behaviour");
    kind = m->choice("kind", ab::behaviourKindName(ab::BehaviourConfig().kind), ab::behaviourNames());
  } else {
    kind = robot.choice("behaviour", ab::kScriptBehaviourName, ab::behaviourNames());
  }
  if (kind == ab::kScriptBehaviourName) {
    if (m) {
      if (m->node().size() > 1) m->fail("kind", "behaviour script takes no overrides (it runs the actions: list)");
      m->finish();
    }
    return std::nullopt;
  }
  ab::parseBehaviourKind(kind, &c.kind);
  if (m) {
    if (auto s = m->optionalMap("field")) readField(*s, c.field);
    if (auto s = m->optionalMap("grid")) readGrid(*s, c.grid);
    if (auto s = m->optionalMap("distribution")) readDistribution(*s, c.distribution);
    if (auto s = m->optionalMap("strategy")) readStrategy(*s, c.strategy);
    if (auto s = m->optionalMap("search")) readSearch(*s, c.search);
    if (auto s = m->optionalMap("search2016")) readSearch2016(*s, c.search2016);
    if (auto s = m->optionalMap("skills")) readSkills(*s, c.skills);
    m->finish();
  }
  return c;
}

std::optional<ab::BehaviourConfig> behaviourFromText(const std::string& kind, const std::string& overrides,
                                                     const std::string& source, std::string* yaml) {
  YAML::Node b = overrides.empty() ? YAML::Node(YAML::NodeType::Map) : YamlReader::parse(overrides, source);
  if (!b.IsMap()) YamlReader(b, source).fail("behaviour overrides must be a map");
  b["kind"] = kind;
  YAML::Node robot(YAML::NodeType::Map);
  robot["behaviour"] = b;
  const YamlReader r(robot, source);
  auto c = readBehaviour(r, yaml);
  r.finish();
  return c;
}

}  // namespace agent::behaviour
