#include "agent/behaviour/WalkTo.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace agent::behaviour {

namespace {
constexpr double kSonarNoEchoMm = 2550.0;  // the NAO's "no echo" reading, 2.55 m
// A teammate counts as oncoming when its heading is within 60 deg of the
// opposite of this robot's: |unit(mine) - unit(its)| = 2 sin(120 deg / 2).
constexpr double kOncomingAxis = 1.7320508;

// A teammate the walk keeps clear of: heard recently and not penalised (a
// penalised robot is off the field).
bool onFieldAndHeard(const Teammate& t, const SkillConfig& s) {
  return !t.penalised && t.time_since_heard <= s.obstacle_timeout;
}
}  // namespace

using blackboard::ActionType;
using blackboard::BodyCommand;

BodyCommand WalkTo::clampToWalk(BodyCommand b, const WalkLimits& w) {
  const double s = std::hypot(b.forward / w.max_forward, b.left / w.max_left);
  if (s > 1) {
    b.forward = static_cast<float>(b.forward / s);
    b.left = static_cast<float>(b.left / s);
  }
  b.turn = static_cast<float>(std::clamp<double>(b.turn, -w.max_turn, w.max_turn));
  return b;
}

Point2 WalkTo::passOncoming(const BehaviourInputs& in, Point2 target, Point2 v) const {
  const double speed = std::hypot(v.x, v.y);
  if (!s_.keep_right || speed < 1e-6) return v;
  const Pose2& me = in.self.pose;
  // Only teammates before the target (or standing on it) are passed.
  const double reach = std::min(s_.pass_lookahead, distance(position(me), target) + 2 * s_.robot_radius);
  double steer = 0;  // rad, + = left
  for (const Teammate& t : in.teammates) {
    if (!onFieldAndHeard(t, s_) || t.fallen) continue;
    // The pair's axis: my heading minus the teammate's, normalised. The
    // teammate computes minus it, and its offset from me minus mine, so
    // both find the same distance ahead and the same side: they can never
    // choose opposite sides (as two robots would that each measured the
    // side against their own way to their own target).
    const double hx = std::cos(me.theta) - std::cos(t.pose.theta), hy = std::sin(me.theta) - std::sin(t.pose.theta);
    const double hn = std::hypot(hx, hy);
    if (hn < kOncomingAxis) continue;  // not facing against me
    const double ux = hx / hn, uy = hy / hn;
    const double rx = t.pose.x - me.x, ry = t.pose.y - me.y;
    const double along = rx * ux + ry * uy;    // mm ahead
    const double lateral = ry * ux - rx * uy;  // mm to the left
    if (along <= 0 || along > reach || std::abs(lateral) >= s_.pass_clearance) continue;
    const double a = lateral >= -s_.robot_radius ? -std::atan2(s_.pass_clearance - lateral, along)  // keep right
                                                 : std::atan2(s_.pass_clearance + lateral, along);
    if (std::abs(a) > std::abs(steer)) steer = a;
  }
  steer = std::clamp(steer, -s_.pass_max_steer, s_.pass_max_steer);
  const double c = std::cos(steer), s = std::sin(steer);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

Point2 WalkTo::repulsion(const BehaviourInputs& in, Point2 target) const {
  struct Obstacle {
    Point2 at;
    double radius;
  };
  std::vector<Obstacle> obs;
  for (const Teammate& t : in.teammates)
    if (onFieldAndHeard(t, s_)) obs.push_back({position(t.pose), s_.robot_radius});
  for (const Point2& p : sonarObstacles(in)) obs.push_back({p, s_.robot_radius});
  for (double sx : {-1.0, 1.0})
    for (double sy : {-1.0, 1.0})
      obs.push_back({{sx * f_.length / 2, sy * f_.goal_post_y}, f_.goal_post_radius});

  const Point2 me = position(in.self.pose);
  const double tx = target.x - me.x, ty = target.y - me.y;
  const double tn = std::max(1e-6, std::hypot(tx, ty));
  Point2 rep{0, 0};
  for (const Obstacle& o : obs) {
    const double dx = me.x - o.at.x, dy = me.y - o.at.y;
    const double centre = std::hypot(dx, dy);
    if (centre < 1e-6) continue;
    // An obstacle standing on the target and further away than it is not
    // pushed against: the robot may stop next to it.
    if (distance(target, o.at) < o.radius + s_.robot_radius && centre > tn) continue;
    const double gap = std::max(50.0, centre - o.radius - s_.robot_radius);  // mm, surface to surface
    if (gap >= s_.avoid_distance) continue;
    const double mag = s_.avoid_gain * (1.0 / gap - 1.0 / s_.avoid_distance);  // mm/s
    const double ux = dx / centre, uy = dy / centre;
    rep.x += mag * ux;
    rep.y += mag * uy;
    // A sideways push as well, on the side of the obstacle away from the
    // line to the target, so a head-on obstacle is walked round instead of
    // stalling in the field's local minimum.
    const double side = (tx * uy - ty * ux) >= 0 ? 1.0 : -1.0;
    rep.x += side * mag * (-ty / tn);
    rep.y += side * mag * (tx / tn);
  }
  return rep;
}

std::vector<Point2> WalkTo::sonarObstacles(const BehaviourInputs& in) const {
  std::vector<Point2> out;
  if (!s_.sonar_avoid) return out;
  const Pose2& me = in.self.pose;
  for (int side : {1, -1}) {  // left, right
    if (!(side > 0 ? in.sonar.near_left : in.sonar.near_right)) continue;
    const double a = me.theta + side * s_.sonar_obstacle_angle;
    out.push_back({me.x + s_.sonar_obstacle_distance * std::cos(a), me.y + s_.sonar_obstacle_distance * std::sin(a)});
  }
  return out;
}

namespace {
// What the walk keeps clear of: teammates on the field and heard
// recently, and what the sonars report close by.
template <typename F>
void forEachNearRobot(const BehaviourInputs& in, const SkillConfig& s, const std::vector<Point2>& sonar, F f) {
  for (const Teammate& t : in.teammates)
    if (onFieldAndHeard(t, s)) f(position(t.pose));
  for (const Point2& p : sonar) f(p);
}
}  // namespace

bool WalkTo::blocked(const BehaviourInputs& in, Point2 target) const {
  const Point2 me = position(in.self.pose);
  const double mine = distance(me, target);
  if (mine > s_.blocked_arrive_distance) return false;
  // What the sonars hear at all (not only near): an obstacle one robot
  // radius beyond the echo, on that side.
  std::vector<Point2> heard;
  if (s_.sonar_avoid)
    for (int side : {1, -1}) {
      const double echo = side > 0 ? in.sonar.left : in.sonar.right;
      if (!(echo < kSonarNoEchoMm)) continue;
      const double a = in.self.pose.theta + side * s_.sonar_obstacle_angle, r = echo + s_.robot_radius;
      heard.push_back({me.x + r * std::cos(a), me.y + r * std::sin(a)});
    }
  bool b = false;
  forEachNearRobot(in, s_, heard, [&](Point2 t) {
    if (distance(t, target) < mine && distance(t, me) <= s_.keep_out_distance + 100.0) b = true;
  });
  return b;
}

bool WalkTo::sonarNear(const BehaviourInputs& in) const {
  return s_.sonar_avoid && (in.sonar.near_left || in.sonar.near_right);
}

Point2 WalkTo::keepOut(const BehaviourInputs& in, Point2 v) const {
  const Point2 me = position(in.self.pose);
  forEachNearRobot(in, s_, sonarObstacles(in), [&](Point2 t) {
    const double dx = t.x - me.x, dy = t.y - me.y;
    const double d = std::hypot(dx, dy);
    if (d < 1e-6 || d > s_.keep_out_distance) return;
    const double ux = dx / d, uy = dy / d;
    const double closing = v.x * ux + v.y * uy;  // mm/s toward the teammate
    if (closing <= 0) return;
    v.x -= closing * ux;
    v.y -= closing * uy;
  });
  return v;
}

WalkToResult WalkTo::tick(const BehaviourInputs& in, Point2 target, std::optional<double> heading,
                          double arrive_distance) const {
  const Pose2& me = in.self.pose;
  const double dist = distance(position(me), target);
  const double final_err = heading ? wrapAngle(*heading - me.theta) : 0.0;
  WalkToResult r;
  const bool back_off = sonarNear(in);
  if (!heading && !back_off && blocked(in, target)) {  // a teammate stands on it: search from here
    r.arrived = true;
    r.body.type = ActionType::STAND;
    return r;
  }
  if (dist <= arrive_distance && std::abs(final_err) <= s_.final_angle_tolerance) {
    r.arrived = true;
    r.body.type = ActionType::STAND;
    return r;
  }
  // Desired field-frame velocity: attraction (capped at max_forward) plus repulsion.
  const double speed = std::min(in.walk.max_forward, s_.walk_gain * dist);
  Point2 v{0, 0};
  if (dist > 1e-6) v = {(target.x - me.x) / dist * speed, (target.y - me.y) / dist * speed};
  v = passOncoming(in, target, v);
  const Point2 rep = repulsion(in, target);
  v.x += rep.x;
  v.y += rep.y;
  v = keepOut(in, v);
  if (back_off)  // step back from what the sonars hear close by
    for (const Point2& o : sonarObstacles(in)) {
      const double d = std::max(1e-6, distance(o, position(me)));
      v.x -= s_.sonar_back_off_speed * (o.x - me.x) / d;
      v.y -= s_.sonar_back_off_speed * (o.y - me.y) / d;
    }

  double want_heading = heading ? *heading : me.theta;
  bool travelling = dist > s_.face_target_distance && !back_off;  // backing off: no turning round
  if (travelling && std::hypot(v.x, v.y) > 1e-6) want_heading = std::atan2(v.y, v.x);
  const double err = wrapAngle(want_heading - me.theta);

  const double c = std::cos(me.theta), s = std::sin(me.theta);
  double fwd = c * v.x + s * v.y, left = -s * v.x + c * v.y;
  if (travelling && std::abs(err) > s_.translate_max_heading_error) fwd = left = 0;  // turn first
  if (dist <= arrive_distance) fwd = left = 0;  // there; only the heading is left

  r.body.type = ActionType::WALK;
  r.body.forward = static_cast<float>(fwd);
  r.body.left = static_cast<float>(left);
  r.body.turn = static_cast<float>(s_.turn_gain * err);
  r.body = clampToWalk(r.body, in.walk);
  return r;
}

}  // namespace agent::behaviour
