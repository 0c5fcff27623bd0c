#include "agent/behaviour/Roles.hpp"

#include <cmath>

#include "agent/behaviour/HeadScan.hpp"

namespace agent::behaviour {

std::optional<Point2> knownBall(const BehaviourInputs& in, const SkillConfig& s) {
  if (in.ball.ever_seen && in.ball.time_since_seen <= s.ball_lost_time) return in.ball.field;
  if (in.team_ball.valid && in.team_ball.time_since_seen <= s.team_ball_max_age)
    return in.team_ball.field;
  return std::nullopt;
}

RoleOutput Searcher::tick(const BehaviourInputs& in, const FindBallResult* fb) {
  RoleOutput o;
  if (auto ball = knownBall(in, c_.skills)) {
    reset();  // the next search starts afresh (2016: from the point nearest the ball)
    const Point2 me = position(in.self.pose);
    const double face = std::atan2(ball->y - me.y, ball->x - me.x);
    const WalkToResult w = walk_.tick(in, *ball, face, c_.skills.approach_distance);
    o.body = w.body;
    o.head = headLookAt(toRobotFrame(in.self.pose, *ball), c_.skills);
    o.activity = w.arrived ? "watch ball" : "walk to ball";
    return o;
  }
  PointSearch::Output s;
  if (use_2017_) {
    if (fb) s = fb2017_.tick(in, *fb);
  } else {
    s = fb2016_.tick(in);
  }
  o.body = s.body;
  o.head = s.head;
  o.searching = true;
  o.activity = behaviourKindName(use_2017_ ? BehaviourKind::FINDBALL_2017 : BehaviourKind::FINDBALL_2016);
  return o;
}

RoleOutput Striker::tick(const BehaviourInputs& in, const FindBallResult* fb) {
  RoleOutput o;
  if (kicking_) {
    const Kick::Output k = kick_.tick(in);
    kicking_ = !k.done;
    o.body = k.body;
    o.head = headLookAt(in.ball.relative, c_.skills);
    o.activity = "kick";
    return o;
  }
  auto ball = knownBall(in, c_.skills);
  if (!ball) return search_.tick(in, fb);
  search_.reset();
  if (!playsBall(in, *ball)) {
    // Support: behind the ball on the line to our own goal, facing the ball.
    const Point2 own_goal{-c_.field.length / 2, 0};
    const double d = std::max(1.0, distance(*ball, own_goal));
    const double s = std::min(c_.skills.support_distance, d);
    const Point2 spot{ball->x + (own_goal.x - ball->x) * s / d, ball->y + (own_goal.y - ball->y) * s / d};
    const WalkToResult w = support_.tick(in, spot, std::atan2(ball->y - spot.y, ball->x - spot.x), 100.0);
    o.body = w.body;
    o.head = headLookAt(toRobotFrame(in.self.pose, *ball), c_.skills);
    o.activity = "support";
    return o;
  }
  const ApproachBall::Output a = approach_.tick(in, *ball);
  o.body = a.body;
  o.head = a.head;
  o.activity = "approach ball";
  // Kick only on a ball seen now by this robot (not a teammate's estimate).
  if (a.lined_up && in.ball.seen_now) {
    kick_.start(in);
    kicking_ = true;
    o.body = kick_.tick(in).body;
    o.activity = "kick";
  }
  return o;
}

bool Striker::playsBall(const BehaviourInputs& in, Point2 ball) {
  if (!c_.skills.team_roles) return true;
  // Every striker of the team decides by the same rule on (nearly) the same
  // data, so they agree: nearest by more than the margin plays; within the
  // margin, the lower player number does (no swapping as the two close in).
  const double mine = distance(position(in.self.pose), ball);
  for (const Teammate& t : in.teammates) {
    if (t.penalised || t.fallen || t.time_since_heard > c_.skills.obstacle_timeout) continue;
    const double theirs = distance(position(t.pose), ball);
    if (theirs < mine - c_.skills.role_margin) return false;
    if (std::fabs(theirs - mine) <= c_.skills.role_margin && t.player < in.player) return false;
  }
  return true;
}

}  // namespace agent::behaviour
