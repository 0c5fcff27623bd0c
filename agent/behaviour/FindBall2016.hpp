// The 2016 FindBall behaviour (thesis 2.3.2): a fixed list of points (table
// 2.1). The point nearest the last known ball is visited first, then the
// others in table order, over and over. The thesis does not say what the
// 2016 robot does at a point; here it does what the 2017 behaviour does
// (scan, spin; same flags), so a comparison measures where each goes, not
// how it looks. Last known ball: own estimate, else the team ball, else
// (never seen) the robot's own position.
#pragma once

#include <vector>

#include "agent/behaviour/PointSearch.hpp"

namespace agent::behaviour {

class FindBall2016 {
 public:
  explicit FindBall2016(const BehaviourConfig& c) : points_(c.search.points_2016), search_(c) {}
  void reset() {
    index_ = -1;
    search_.reset();
  }
  PointSearch::Output tick(const BehaviourInputs& in);
  int index() const { return index_; }  // 0-based into the points, -1 before starting
  Point2 point() const { return search_.point(); }

  static int startIndex(const std::vector<Point2>& points, Point2 last_ball);
  static int nextIndex(int index, int count) { return (index + 1) % count; }
  static Point2 lastKnownBall(const BehaviourInputs& in);

 private:
  std::vector<Point2> points_;
  PointSearch search_;
  int index_ = -1;
};

}  // namespace agent::behaviour
