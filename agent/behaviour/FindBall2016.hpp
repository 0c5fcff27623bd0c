// The 2016 FindBall behaviour (thesis 2.3.2): a fixed list of points (table
// 2.1). The point nearest the last known ball is visited first, then the
// others in table order (clockwise seen from above, as 2.3.2 says), over and
// over. The 2016 code itself was never released; what the thesis leaves
// open is filled from what the era's released code did
// (Search2016Config, BehaviourConfig.hpp):
//
// ERA style (the default):
//  - Last known ball: the ball estimate as the era's localisation kept it.
//    With no estimate yet its filter starts the ball at the field centre
//    (rUNSWift 2018 release, perception/localisation/
//    MultiGaussianDistribution.cpp, resetDistributionToPenalisedPose: ball
//    mean (0, 0) when there is no earlier mode; a penalty keeps the last
//    ball estimate), so a search by a robot that has never seen the ball
//    (the thesis's trials: every program started fresh) begins at the point
//    nearest (0, 0): table 2.1's point 3 (0, 1000) (tied with point 7
//    (0, -1000); the earlier point in the table wins, as a min() over the
//    list in order would).
//  - The points are walked through, not stopped at: within pass_distance
//    the next point becomes the target, so the walk never stops.
//  - The head does what the era's default head skill did with the ball
//    lost (rUNSWift 2016 release, skills/HeadSkill.py): it looks toward the
//    ball estimate; or, configured (head: scan), the HeadScan sweep.
// STOP_SCAN_SPIN style: at every point stop, scan, spin (PointSearch, the
//   2017 behaviour's stop), and with no sighting start at the point
//   nearest the robot itself (the earlier simswift variant, kept as it was).
#pragma once

#include <vector>

#include "agent/behaviour/PointSearch.hpp"

namespace agent::behaviour {

class FindBall2016 {
 public:
  explicit FindBall2016(const BehaviourConfig& c)
      : points_(c.search.points_2016), c16_(c.search2016), skills_(c.skills), search_(c),
        walk_(c.skills, c.field) {}
  void reset() {
    index_ = -1;
    search_.reset();
  }
  PointSearch::Output tick(const BehaviourInputs& in);
  int index() const { return index_; }  // 0-based into the points, -1 before starting
  Point2 point() const { return index_ >= 0 && index_ < static_cast<int>(points_.size()) ? points_[index_] : Point2{}; }
  bool era() const { return c16_.style == Search2016Style::ERA; }

  static int startIndex(const std::vector<Point2>& points, Point2 last_ball);
  static int nextIndex(int index, int count) { return (index + 1) % count; }
  // STOP_SCAN_SPIN: own estimate, else the team ball, else the robot's own position.
  static Point2 lastKnownBall(const BehaviourInputs& in);
  // ERA: the ball estimate as the era's localisation held it: the own
  // estimate, else the team ball, else (never seen) the field centre.
  static Point2 eraBallEstimate(const BehaviourInputs& in);

 private:
  PointSearch::Output tickEra(const BehaviourInputs& in);
  blackboard::HeadCommand eraHead(const BehaviourInputs& in, Point2 ball);

  std::vector<Point2> points_;
  Search2016Config c16_;
  SkillConfig skills_;
  PointSearch search_;
  WalkTo walk_;
  HeadScan scan_{skills_};
  int index_ = -1;
  bool near_pitch_ = true;   // the era's head skill starts with the near pitch
};

}  // namespace agent::behaviour
