#include "agent/behaviour/SimpleUtilityCalculator.hpp"

#include <algorithm>
#include <cmath>

namespace agent::behaviour {

double SimpleUtilityCalculator::travelTime(const Pose2& from, Point2 to, const WalkLimits& walk,
                                           const StrategyConfig& c) {
  const double dist = distance(position(from), to);
  double turn = 0;
  if (dist > c.face_distance)
    turn = std::abs(wrapAngle(std::atan2(to.y - from.y, to.x - from.x) - from.theta));
  const double t = turn / walk.max_turn + dist / walk.max_forward;
  return std::max(t, c.min_travel_time);
}

double SimpleUtilityCalculator::utility(const PositionalDistribution& d, int segment,
                                        const BehaviourInputs& in) const {
  return d.probability(segment) / travelTime(in.self.pose, d.centre(segment), in.walk, config_);
}

}  // namespace agent::behaviour
