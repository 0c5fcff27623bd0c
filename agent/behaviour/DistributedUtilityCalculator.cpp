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

double DistributedUtilityCalculator::utility(const PositionalDistribution& d, int segment,
                                             const BehaviourInputs& in) const {
  return local_->utility(d, segment, in) / (visitors(d, segment, in) + 1);
}

}  // namespace agent::behaviour
