// DistributionComponent (thesis 4.2.1.1): one transformation of the
// distribution per tick, run in turn by CompositeDistributionGenerator.
#pragma once

#include "agent/behaviour/BehaviourInputs.hpp"
#include "agent/behaviour/PositionalDistribution.hpp"

namespace agent::behaviour {

class DistributionComponent {
 public:
  virtual ~DistributionComponent() = default;
  virtual const char* name() const = 0;
  // dt: s since the previous update.
  virtual void apply(PositionalDistribution& d, const BehaviourInputs& in, double dt) = 0;
};

}  // namespace agent::behaviour
