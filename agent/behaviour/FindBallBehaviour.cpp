#include "agent/behaviour/FindBallBehaviour.hpp"

namespace agent::behaviour {

PointSearch::Output FindBallBehaviour::tick(const BehaviourInputs& in, const FindBallResult& fb) {
  const SearchChoice& ch = fb.choice;
  const bool need_point = segment_ < 0 || search_.phase() == PointSearch::Phase::DONE ||
                          search_.phase() == PointSearch::Phase::IDLE;
  if (need_point && ch.segment >= 0) {
    segment_ = ch.segment;
    search_.start(ch.point, in.time);
  } else if (search_.phase() == PointSearch::Phase::WALK && ch.segment >= 0 &&
             ch.segment != segment_ && segment_ < static_cast<int>(ch.utilities.size()) &&
             ch.utilities[ch.segment] > c_.switch_hysteresis * ch.utilities[segment_]) {
    segment_ = ch.segment;
    search_.retarget(ch.point);
  }
  return search_.tick(in);
}

}  // namespace agent::behaviour
