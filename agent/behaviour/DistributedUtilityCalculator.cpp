#include "agent/behaviour/DistributedUtilityCalculator.hpp"

namespace agent::behaviour {

int DistributedUtilityCalculator::visitors(const PositionalDistribution& d, int segment,
                                           const BehaviourInputs& in) const {
  int v = 0;
  for (const Teammate& t : in.teammates) {
    if (!t.search || t.penalised || t.time_since_heard > config_.teammate_timeout) continue;
    if (t.search->columns != d.columns() || t.search->rows != d.rows()) continue;
    if (t.search->segment == segment) ++v;
  }
  return v;
}

bool DistributedUtilityCalculator::claimedByTeammate(const PositionalDistribution& d, int segment,
                                                     const BehaviourInputs& in) const {
  const Point2 centre = d.centre(segment);
  const double mine = distance(position(in.self.pose), centre);  // mm
  for (const Teammate& t : in.teammates) {
    if (!t.search || t.penalised || t.time_since_heard > config_.teammate_timeout) continue;
    if (t.search->columns != d.columns() || t.search->rows != d.rows() || t.search->segment != segment) continue;
    const double theirs = distance(position(t.pose), centre);
    if (theirs < mine || (theirs == mine && t.player < in.player)) return true;
  }
  return false;
}

double DistributedUtilityCalculator::utility(const PositionalDistribution& d, int segment,
                                             const BehaviourInputs& in) const {
  if (config_.exclusive_segments && claimedByTeammate(d, segment, in)) return 0.0;
  return local_->utility(d, segment, in) / (visitors(d, segment, in) + 1);
}

}  // namespace agent::behaviour
