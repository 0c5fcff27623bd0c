// UtilityCalculator (thesis 4.2.2): the utility of searching segment j.
#pragma once

#include "agent/behaviour/BehaviourInputs.hpp"
#include "agent/behaviour/PositionalDistribution.hpp"

namespace agent::behaviour {

class UtilityCalculator {
 public:
  virtual ~UtilityCalculator() = default;
  virtual double utility(const PositionalDistribution& d, int segment,
                         const BehaviourInputs& in) const = 0;
};

}  // namespace agent::behaviour
