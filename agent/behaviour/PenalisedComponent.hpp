// PenalisedComponent: a penalised robot is taken off the field and put back
// at the touch line, and the ball has moved meanwhile: uniform while penalised.
#pragma once

#include "agent/behaviour/DistributionComponent.hpp"

namespace agent::behaviour {

class PenalisedComponent : public DistributionComponent {
 public:
  const char* name() const override { return "PenalisedComponent"; }
  void apply(PositionalDistribution& d, const BehaviourInputs& in, double) override {
    if (in.game.penalised) d.reset();
  }
};

}  // namespace agent::behaviour
