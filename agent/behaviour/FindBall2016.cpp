#include "agent/behaviour/FindBall2016.hpp"

namespace agent::behaviour {

Point2 FindBall2016::lastKnownBall(const BehaviourInputs& in) {
  if (in.ball.ever_seen) return in.ball.field;
  if (in.team_ball.valid) return in.team_ball.field;
  return position(in.self.pose);
}

int FindBall2016::startIndex(const std::vector<Point2>& points, Point2 last_ball) {
  int best = -1;
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
    if (best < 0 || distance(points[i], last_ball) < distance(points[best], last_ball)) best = i;
  return best;
}

PointSearch::Output FindBall2016::tick(const BehaviourInputs& in) {
  if (points_.empty()) return {};
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
