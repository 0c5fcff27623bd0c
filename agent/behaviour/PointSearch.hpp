// PointSearch: what both FindBall behaviours do with one search point:
// walk to it (head sweeping if scan_while_walking), then on arrival a head
// scan (scan_at_point), then one full spin (spin_at_point), then done.
#pragma once

#include "agent/behaviour/HeadScan.hpp"
#include "agent/behaviour/Spin.hpp"
#include "agent/behaviour/WalkTo.hpp"

namespace agent::behaviour {

class PointSearch {
 public:
  enum class Phase { IDLE, WALK, SCAN, SPIN, DONE };
  PointSearch(const BehaviourConfig& c)
      : c_(c.search), walk_(c.skills, c.field), scan_(c.skills), spin_(c.skills) {}

  void start(Point2 point, double time);  // (re)targets and walks
  void retarget(Point2 point) { point_ = point; }  // keeps walking, new point
  void reset() { phase_ = Phase::IDLE; }
  struct Output {
    blackboard::BodyCommand body;
    blackboard::HeadCommand head;
  };
  Output tick(const BehaviourInputs& in);
  Phase phase() const { return phase_; }
  Point2 point() const { return point_; }

 private:
  SearchBehaviourConfig c_;
  WalkTo walk_;
  HeadScan scan_;
  Spin spin_;
  Phase phase_ = Phase::IDLE;
  Point2 point_;
};

const char* phaseName(PointSearch::Phase p);

}  // namespace agent::behaviour
