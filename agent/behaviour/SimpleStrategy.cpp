#include "agent/behaviour/SimpleStrategy.hpp"

namespace agent::behaviour {

SearchChoice SimpleStrategy::choose(const PositionalDistribution& d, const BehaviourInputs& in) {
  SearchChoice c;
  c.utilities.resize(d.size());
  for (int j = 0; j < d.size(); ++j) {
    c.utilities[j] = calc_->utility(d, j, in);
    if (c.segment < 0 || c.utilities[j] > c.utilities[c.segment]) c.segment = j;
  }
  if (c.segment >= 0) c.point = d.centre(c.segment);
  return c;
}

}  // namespace agent::behaviour
