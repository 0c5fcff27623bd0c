#include "agent/behaviour/FindBall2016.hpp"

#include <algorithm>
#include <cmath>

namespace agent::behaviour {

Point2 FindBall2016::lastKnownBall(const BehaviourInputs& in) {
  if (in.ball.ever_seen) return in.ball.field;
  if (in.team_ball.valid) return in.team_ball.field;
  return position(in.self.pose);
}

Point2 FindBall2016::eraBallEstimate(const BehaviourInputs& in) {
  if (in.ball.ever_seen) return in.ball.field;
  if (in.team_ball.valid) return in.team_ball.field;
  return {0, 0};  // field centre
}

int FindBall2016::startIndex(const std::vector<Point2>& points, Point2 last_ball) {
  int best = -1;
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
    if (best < 0 || distance(points[i], last_ball) < distance(points[best], last_ball)) best = i;
  return best;
}

blackboard::HeadCommand FindBall2016::eraHead(const BehaviourInputs& in, Point2 ball) {
  const Point2 rel = toRobotFrame(in.self.pose, ball);  // mm, robot frame
  const double d = std::hypot(rel.x, rel.y);
  // HeadSkill.py's close-in hysteresis: near below 0.9 x, far above 1.1 x.
  if (near_pitch_ && d > 1.1 * c16_.head_near_distance) near_pitch_ = false;
  if (!near_pitch_ && d < 0.9 * c16_.head_near_distance) near_pitch_ = true;
  blackboard::HeadCommand h;
  h.yaw = static_cast<float>(
      std::clamp(d > 1e-6 ? std::atan2(rel.y, rel.x) : 0.0, -skills_.head_yaw_limit, skills_.head_yaw_limit));
  h.pitch = static_cast<float>(near_pitch_ ? c16_.head_near_pitch : c16_.head_far_pitch);
  h.yaw_speed = static_cast<float>(std::min(skills_.head_speed_limit, c16_.head_yaw_speed));
  h.pitch_speed = static_cast<float>(std::min(skills_.head_speed_limit, c16_.head_pitch_speed));
  return h;
}

PointSearch::Output FindBall2016::tickEra(const BehaviourInputs& in) {
  const int n = static_cast<int>(points_.size());
  if (index_ < 0) {
    index_ = startIndex(points_, eraBallEstimate(in));
    scan_.start(in.time);
  }
  // Passing through: the next point as soon as this one is within reach
  // (a teammate standing on it counts too), so the walk never stops.
  WalkToResult w = walk_.tick(in, points_[index_], std::nullopt, c16_.pass_distance);
  for (int k = 0; w.arrived && k < n; ++k) {
    index_ = nextIndex(index_, n);
    w = walk_.tick(in, points_[index_], std::nullopt, c16_.pass_distance);
  }
  PointSearch::Output o;
  o.body = w.body;
  o.head = c16_.head == Search2016Head::SCAN ? scan_.tick(in.time) : eraHead(in, eraBallEstimate(in));
  return o;
}

PointSearch::Output FindBall2016::tick(const BehaviourInputs& in) {
  if (points_.empty()) return {};
  if (era()) return tickEra(in);
  if (index_ < 0) {
    index_ = startIndex(points_, lastKnownBall(in));
    search_.start(points_[index_], in.time);
  } else if (search_.phase() == PointSearch::Phase::DONE) {
    index_ = nextIndex(index_, static_cast<int>(points_.size()));
    search_.start(points_[index_], in.time);
  }
  return search_.tick(in);
}

}  // namespace agent::behaviour
