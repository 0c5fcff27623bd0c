#include "agent/behaviour/PointSearch.hpp"

namespace agent::behaviour {

const char* phaseName(PointSearch::Phase p) {
  switch (p) {
    case PointSearch::Phase::IDLE: return "idle";
    case PointSearch::Phase::WALK: return "walk";
    case PointSearch::Phase::SCAN: return "scan";
    case PointSearch::Phase::SPIN: return "spin";
    case PointSearch::Phase::DONE: return "done";
  }
  return "?";
}

void PointSearch::start(Point2 point, double time) {
  point_ = point;
  phase_ = Phase::WALK;
  scan_.start(time);
}

PointSearch::Output PointSearch::tick(const BehaviourInputs& in) {
  Output o;
  o.body.type = blackboard::ActionType::STAND;
  o.head = scan_.tick(in.time);
  if (phase_ == Phase::WALK) {
    const WalkToResult w = walk_.tick(in, point_, std::nullopt, c_.arrive_distance);
    if (!w.arrived) {
      o.body = w.body;
      if (!c_.scan_while_walking) o.head = blackboard::HeadCommand{};
      return o;
    }
    phase_ = c_.scan_at_point ? Phase::SCAN : Phase::SPIN;
    scan_.start(in.time);
    spin_.start(in.self.pose);
    if (!c_.scan_at_point && !c_.spin_at_point) phase_ = Phase::DONE;
  }
  if (phase_ == Phase::SCAN) {
    if (!scan_.sweepDone(in.time)) {
      o.head = scan_.tick(in.time);
      return o;
    }
    phase_ = c_.spin_at_point ? Phase::SPIN : Phase::DONE;
    spin_.start(in.self.pose);
  }
  if (phase_ == Phase::SPIN) {
    const Spin::Output s = spin_.tick(in);
    if (!s.done) {
      o.body = s.body;
      o.head = s.head;
      return o;
    }
    phase_ = Phase::DONE;
  }
  return o;  // IDLE / DONE: stand, head sweeping
}

}  // namespace agent::behaviour
