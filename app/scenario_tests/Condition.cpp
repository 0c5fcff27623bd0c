#include "app/scenario_tests/Condition.hpp"

#include <cmath>
#include <cstdio>

#include "app/experiment/Trial.hpp"
#include "sim/game/GameController.hpp"

namespace simswift::scenario_tests {

using common::config::Range;
using common::config::YamlReader;

namespace {

const std::vector<std::string> kTimeOps = {"all", "any", "not", "within", "eventually", "always", "never", "at_end"};
const std::vector<std::string> kStateOps = {"all",       "any",          "not",        "ball_in_goal", "ball_in_zone",
                                            "near_ball", "near_pose",    "fallen",     "falls",        "penalised",
                                            "touched_ball", "game_state", "team_packets", "time",      "robots_within"};

std::string flowText(const YAML::Node& n) {
  YAML::Emitter e;
  e << YAML::Flow << n;
  return e.c_str();
}

// The one operator key of map `m` (ConfigError naming a misspelling, an
// operator of the other level, or two keys).
std::string operatorOf(const YamlReader& m, const std::vector<std::string>& ops, const std::vector<std::string>& other,
                       const char* level) {
  if (!m.node().IsMap() || m.node().size() == 0)
    m.fail(std::string("must be a map with one ") + level + " operator (" + (level[0] == 't' ? "within, eventually, always, never, at_end, all, any, not" : "ball_in_goal, near_ball, fallen, ...") + ")");
  std::string found;
  for (const YamlReader::Key& key : m.keys()) {
    const std::string& k = key.name;
    for (const std::string& op : ops)
      if (k == op) {
        if (!found.empty())
          m.fail(k, "one operator per map (got " + found + " and " + k + "): combine them with all: [...] or any: [...]");
        found = k;
      }
  }
  if (found.empty()) {
    for (const YamlReader::Key& key : m.keys()) {
      const std::string& k = key.name;
      for (const std::string& op : other)
        if (k == op)
          m.fail(k, level[0] == 't'
                        ? "a state predicate needs a time: wrap it in within:, eventually:, always:, never: or at_end:"
                        : "a temporal operator cannot be inside another one");
    }
    for (const std::string& op : ops) (void)m.has(op);  // known: finish() names near misses
    m.finish();
    m.fail("no operator");
  }
  for (const std::string& op : ops) (void)m.has(op);  // a stray key's message lists them all
  return found;
}

int readRobot(const YamlReader& m, const std::string& key, int num_robots) {
  const std::string s = m.string(key);
  if (s == "any") return StateNode::kAny;
  if (s == "blue") return StateNode::kBlue;
  if (s == "red") return StateNode::kRed;
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0')
    m.fail(key, "must be a robot's index in the scenario (0.." + std::to_string(num_robots - 1) +
                    "), any, blue or red (got " + s + ")");
  if (v < 0 || v >= num_robots)
    m.fail(key, "no robot " + s + " (the scenario has " + std::to_string(num_robots) + ", indices from 0)");
  return static_cast<int>(v);
}

int readSide(const YamlReader& m, const std::string& key, bool any_allowed) {
  const std::string s = any_allowed ? m.choice(key, "", {"blue", "red", "any"}) : m.choice(key, "", {"blue", "red"});
  if (s.empty()) m.missing(key, "required");
  return s == "blue" ? 0 : s == "red" ? 1 : -1;
}

void readInterval(const YamlReader& m, const std::string& key, double* lo, double* hi) {
  const std::vector<double> v = m.numbers(key, 2, Range::closed(-100, 100));
  if (v[0] > v[1]) m.fail(key, "must be [low, high] with low <= high");
  *lo = v[0];
  *hi = v[1];
}

StateNode readState(const YamlReader& m, int num_robots);

// A predicate whose value is a scalar (fallen: 0) or a map (near_ball: {...}):
// the value's reader when it is a map. A scalar value is read from `m` itself.
StateNode readStateOp(const YamlReader& m, const std::string& op, int num_robots) {
  using K = StateNode::Kind;
  StateNode s;
  s.text = flowText(m.node());
  if (op == "all" || op == "any") {
    s.kind = op == "all" ? K::All : K::Any;
    const std::vector<YamlReader> items = m.list(op);
    if (items.empty()) m.fail(op, "needs at least one condition");
    for (const YamlReader& it : items) s.children.push_back(readState(it, num_robots));
  } else if (op == "not") {
    s.kind = K::Not;
    s.children.push_back(readState(m.map(op), num_robots));
  } else if (op == "ball_in_goal") {
    s.kind = K::BallInGoal;
    s.side = readSide(m, op, true);
  } else if (op == "ball_in_zone") {
    s.kind = K::BallInZone;
    const YamlReader z = m.map(op);
    readInterval(z, "x", &s.x0, &s.x1);
    readInterval(z, "y", &s.y0, &s.y1);
    z.finish();
  } else if (op == "near_ball" || op == "near_pose") {
    s.kind = op == "near_ball" ? K::NearBall : K::NearPose;
    const YamlReader z = m.map(op);
    s.robot = readRobot(z, "robot", num_robots);
    s.distance = z.number("distance", Range::positive());
    if (s.kind == K::NearBall) {
      s.count = z.integer("count", 1, Range::closed(1, 64));
    } else {
      s.x0 = z.number("x", Range::closed(-100, 100));
      s.y0 = z.number("y", Range::closed(-100, 100));
    }
    z.finish();
  } else if (op == "fallen" || op == "penalised" || op == "touched_ball") {
    s.kind = op == "fallen" ? K::Fallen : op == "penalised" ? K::Penalised : K::TouchedBall;
    s.robot = readRobot(m, op, num_robots);
  } else if (op == "falls") {
    s.kind = K::Falls;
    const YamlReader z = m.map(op);
    s.robot = readRobot(z, "robot", num_robots);
    s.count = z.integer("at_least", Range::closed(1, 1000000));
    z.finish();
  } else if (op == "game_state") {
    s.kind = K::GameState;
    std::vector<std::string> names = game::stateNames();
    const std::string v = m.choice(op, "", names);
    if (v.empty()) m.missing(op, "required");
    for (int k = 0; k < static_cast<int>(names.size()); ++k)
      if (names[k] == v) s.state = static_cast<common::libagent::GameStateValue>(k);
  } else if (op == "team_packets") {
    s.kind = K::TeamPackets;
    const YamlReader z = m.map(op);
    s.side = readSide(z, "team", false);
    s.count = z.integer("at_most", Range::closed(0, 100000000));
    z.finish();
  } else if (op == "time") {
    s.kind = K::Time;
    const YamlReader z = m.map(op);
    s.seconds = z.number("at_least", Range::nonNegative());
    z.finish();
  } else if (op == "robots_within") {
    s.kind = K::RobotsWithin;
    s.distance = m.number(op, Range::positive());
  }
  return s;
}

StateNode readState(const YamlReader& m, int num_robots) {
  const std::string op = operatorOf(m, kStateOps, {"within", "eventually", "always", "never", "at_end"}, "state");
  StateNode s = readStateOp(m, op, num_robots);
  m.finish();
  return s;
}

TimeNode readTime(const YamlReader& m, int num_robots, double time_limit) {
  const std::string op = operatorOf(m, kTimeOps, kStateOps, "time");
  TimeNode n;
  n.text = flowText(m.node());
  using K = TimeNode::Kind;
  if (op == "all" || op == "any") {
    n.kind = op == "all" ? K::All : K::Any;
    const std::vector<YamlReader> items = m.list(op);
    if (items.empty()) m.fail(op, "needs at least one condition");
    for (const YamlReader& it : items) n.children.push_back(readTime(it, num_robots, time_limit));
  } else if (op == "not") {
    n.kind = K::Not;
    n.children.push_back(readTime(m.map(op), num_robots, time_limit));
  } else if (op == "within") {
    n.kind = K::Within;
    const YamlReader w = m.map(op);
    n.seconds = w.number("seconds", Range::openClosed(0, time_limit));
    n.that = readState(w.map("that"), num_robots);
    w.finish();
  } else if (op == "eventually") {
    n.kind = K::Within;
    n.seconds = time_limit;
    n.that = readState(m.map(op), num_robots);
  } else {
    n.kind = op == "at_end" ? K::AtEnd : K::Always;
    n.negate = op == "never";
    n.that = readState(m.map(op), num_robots);
  }
  m.finish();
  return n;
}

bool selected(int selector, int index, const RobotTruth& r) {
  if (selector >= 0) return selector == index;
  if (selector == StateNode::kBlue) return r.side == 0;
  if (selector == StateNode::kRed) return r.side == 1;
  return true;
}

}  // namespace

TimeNode readCondition(const YamlReader& parent, const std::string& key, int num_robots, double time_limit) {
  return readTime(parent.map(key), num_robots, time_limit);
}

bool hasEventually(const TimeNode& n) {
  if (n.kind == TimeNode::Kind::Within) return true;
  for (const TimeNode& c : n.children)
    if (hasEventually(c)) return true;
  return false;
}

bool StateNode::eval(const Truth& t, const FieldConfig& f) const {
  const int n = static_cast<int>(t.robots.size());
  auto ballDistance = [&](const RobotTruth& r) { return std::hypot(r.x - t.ball_x, r.y - t.ball_y); };
  switch (kind) {
    case Kind::All:
      for (const StateNode& c : children)
        if (!c.eval(t, f)) return false;
      return true;
    case Kind::Any:
      for (const StateNode& c : children)
        if (c.eval(t, f)) return true;
      return false;
    case Kind::Not: return !children[0].eval(t, f);
    case Kind::BallInGoal:
      return side < 0 ? ballInGoal(t, f, 0) || ballInGoal(t, f, 1) : ballInGoal(t, f, side);
    case Kind::BallInZone:
      return t.has_ball && t.ball_x >= x0 && t.ball_x <= x1 && t.ball_y >= y0 && t.ball_y <= y1;
    case Kind::NearBall: {
      if (!t.has_ball) return false;
      int64_t near = 0;
      for (int i = 0; i < n; ++i)
        if (selected(robot, i, t.robots[i]) && ballDistance(t.robots[i]) <= distance) ++near;
      return near >= count;
    }
    case Kind::NearPose:
      for (int i = 0; i < n; ++i)
        if (selected(robot, i, t.robots[i]) && std::hypot(t.robots[i].x - x0, t.robots[i].y - y0) <= distance)
          return true;
      return false;
    case Kind::Fallen:
    case Kind::Penalised:
    case Kind::TouchedBall:
      for (int i = 0; i < n; ++i) {
        if (!selected(robot, i, t.robots[i])) continue;
        const RobotTruth& r = t.robots[i];
        if ((kind == Kind::Fallen && r.fallen) || (kind == Kind::Penalised && r.penalised) ||
            (kind == Kind::TouchedBall && r.touched_ball))
          return true;
      }
      return false;
    case Kind::Falls: {
      int64_t falls = 0;
      for (int i = 0; i < n; ++i)
        if (selected(robot, i, t.robots[i])) falls += t.robots[i].falls;
      return falls >= count;
    }
    case Kind::GameState: return t.state == state;
    case Kind::TeamPackets: return t.team_sent[side] <= count;
    case Kind::Time: return t.t >= seconds - 1e-9;
    case Kind::RobotsWithin:
      for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
          if (std::hypot(t.robots[i].x - t.robots[j].x, t.robots[i].y - t.robots[j].y) < distance) return true;
      return false;
  }
  return false;
}

namespace {

size_t countNodes(const TimeNode& n) {
  size_t c = 1;
  for (const TimeNode& k : n.children) c += countNodes(k);
  return c;
}

std::string seconds2(double t) { return experiment::fixed(t, 2) + " s"; }

}  // namespace

ConditionRun::ConditionRun(const TimeNode& root, const FieldConfig& field)
    : root_(root), field_(field), states_(countNodes(root)), can_stop_early_(hasEventually(root)) {}

// The temporal operators after one tick (at_end: the time limit).
void ConditionRun::advance(const TimeNode& n, size_t& id, const Truth& t, bool at_end) {
  State& s = states_[id++];
  using K = TimeNode::Kind;
  switch (n.kind) {
    case K::Within:
      if (s.v != Verdict3::Pending) return;
      if (t.t <= n.seconds + 1e-9 && n.that.eval(t, field_)) s = {Verdict3::True, t.t};
      else if (t.t >= n.seconds - 1e-9 || at_end) s = {Verdict3::False, std::min(t.t, n.seconds)};
      return;
    case K::Always:
      if (s.v != Verdict3::Pending) return;
      if (n.that.eval(t, field_) == n.negate) s = {Verdict3::False, t.t};
      else if (at_end) s = {Verdict3::True, t.t};
      return;
    case K::AtEnd:
      if (s.v == Verdict3::Pending && at_end) s = {n.that.eval(t, field_) ? Verdict3::True : Verdict3::False, t.t};
      return;
    default:
      for (const TimeNode& c : n.children) advance(c, id, t, at_end);
  }
}

// The node's value from its operators' states (kept in states_ for
// firstFailure). optimistic: a pending always / never counts as holding,
// but only on a path of `all`s from the root: under `any` or `not` an
// invariant that might still break decides nothing yet.
Verdict3 ConditionRun::value(const TimeNode& n, size_t& id, bool optimistic) {
  State& s = states_[id++];
  using K = TimeNode::Kind;
  switch (n.kind) {
    case K::Within:
    case K::AtEnd: return s.v;
    case K::Always: return s.v == Verdict3::Pending && optimistic ? Verdict3::True : s.v;
    case K::Not: {
      const Verdict3 v = value(n.children[0], id, false);
      s.v = v == Verdict3::Pending ? v : v == Verdict3::True ? Verdict3::False : Verdict3::True;
      return s.v;
    }
    case K::All:
    case K::Any: {
      const Verdict3 decisive = n.kind == K::All ? Verdict3::False : Verdict3::True;
      bool any_decisive = false, all_other = true;
      for (const TimeNode& c : n.children) {
        const Verdict3 v = value(c, id, optimistic && n.kind == K::All);
        any_decisive = any_decisive || v == decisive;
        all_other = all_other && v != Verdict3::Pending && v != decisive;
      }
      s.v = any_decisive ? decisive
            : all_other  ? (decisive == Verdict3::False ? Verdict3::True : Verdict3::False)
                         : Verdict3::Pending;
      return s.v;
    }
  }
  return Verdict3::Pending;
}

// The earliest operator whose outcome made the condition fail: from the
// root, only into the children that decided their parent's failing value
// (under an odd number of `not`s, a value that held).
void ConditionRun::firstFailure(const TimeNode& n, size_t& id, bool positive) {
  const State& s = states_[id++];
  using K = TimeNode::Kind;
  const Verdict3 bad = positive ? Verdict3::False : Verdict3::True;
  if (n.kind == K::Not || n.kind == K::All || n.kind == K::Any) {
    for (const TimeNode& c : n.children) {
      const size_t child = id;
      const bool child_positive = n.kind == K::Not ? !positive : positive;
      const Verdict3 child_bad = child_positive ? Verdict3::False : Verdict3::True;
      if (s.v == bad && states_[child].v == child_bad) firstFailure(c, id, child_positive);
      else id += countNodes(c);
    }
    return;
  }
  if (s.v != bad) return;
  if (!failure_.empty() && s.t >= failure_t_) return;
  std::string what;
  if (!positive) what = "not " + n.text + ": it held at " + seconds2(s.t);
  else if (n.kind == K::Within) what = n.text + ": not met by " + seconds2(s.t);
  else if (n.kind == K::Always) what = n.text + ": broken at " + seconds2(s.t);
  else what = n.text + ": false at the end (" + seconds2(s.t) + ")";
  failure_ = what;
  failure_t_ = s.t;
}

Verdict3 ConditionRun::decide(const Truth& t, bool at_end) {
  size_t id = 0;
  advance(root_, id, t, at_end);
  id = 0;
  Verdict3 v = value(root_, id, false);
  if (v == Verdict3::Pending && can_stop_early_ && !at_end) {
    id = 0;
    if (value(root_, id, true) == Verdict3::True) v = Verdict3::True;
    id = 0;
    (void)value(root_, id, false);  // the stored composite values as they are
  }
  if (v != Verdict3::Pending) decided_t_ = t.t;
  if (v == Verdict3::False) {
    id = 0;
    firstFailure(root_, id, true);
  }
  return v;
}

Verdict3 ConditionRun::update(const Truth& t) { return decide(t, false); }

Verdict3 ConditionRun::finish(const Truth& t) { return decide(t, true); }

}  // namespace simswift::scenario_tests
