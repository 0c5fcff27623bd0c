// SimpleUtilityCalculator (thesis 4.2.2.1): benefit / cost,
//   U(S_j) = P(S_j) / Time(pos, centre(S_j)),
// with Time the walk's time to get there: turn on the spot to face the
// centre at the walk's max turn speed, then walk straight at its max forward
// speed (the walk's real speeds, from BehaviourInputs::walk):
//   Time = |heading error| / max_turn + distance / max_forward,
// the turn not counted within face_distance of the centre, and never below
// min_travel_time (a robot on the centre would otherwise divide by zero).
#pragma once

#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/behaviour/UtilityCalculator.hpp"

namespace agent::behaviour {

class SimpleUtilityCalculator : public UtilityCalculator {
 public:
  explicit SimpleUtilityCalculator(const StrategyConfig& c) : config_(c) {}
  double utility(const PositionalDistribution& d, int segment,
                 const BehaviourInputs& in) const override;
  // s, see above.
  static double travelTime(const Pose2& from, Point2 to, const WalkLimits& walk,
                           const StrategyConfig& c);

 private:
  StrategyConfig config_;
};

}  // namespace agent::behaviour
