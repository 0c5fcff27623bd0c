// The 2017 FindBall behaviour (thesis 4.2.3): with no search point, take
// the FindBall class's suggestion; walk to it, scan, spin, then take the
// next suggestion. While walking it follows a new suggestion only if that
// segment's utility beats the current target's by switch_hysteresis (so two
// robots that picked the same segment in the same tick can part once they
// hear each other, without dithering between near-equal segments).
// The caller stops it when this robot or a teammate sees the ball.
#pragma once

#include "agent/behaviour/FindBall.hpp"
#include "agent/behaviour/PointSearch.hpp"

namespace agent::behaviour {

class FindBallBehaviour {
 public:
  explicit FindBallBehaviour(const BehaviourConfig& c) : c_(c.search), search_(c) {}
  void reset() {
    segment_ = -1;
    search_.reset();
  }
  PointSearch::Output tick(const BehaviourInputs& in, const FindBallResult& fb);
  int segment() const { return segment_; }  // 0-based target segment, -1 none
  Point2 point() const { return search_.point(); }
  PointSearch::Phase phase() const { return search_.phase(); }

 private:
  SearchBehaviourConfig c_;
  PointSearch search_;
  int segment_ = -1;
};

}  // namespace agent::behaviour
