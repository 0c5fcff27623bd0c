// EntropyComponent: information grows stale, so the distribution converges
// to uniform: P_j += (1 - exp(-entropy_rate * dt)) * (1/J - P_j), normalised.
#pragma once

#include <cmath>

#include "agent/behaviour/DistributionComponent.hpp"

namespace agent::behaviour {

class EntropyComponent : public DistributionComponent {
 public:
  explicit EntropyComponent(double rate_per_s) : rate_(rate_per_s) {}
  const char* name() const override { return "EntropyComponent"; }
  void apply(PositionalDistribution& d, const BehaviourInputs&, double dt) override {
    if (dt > 0) d.blendTowardUniform(1.0 - std::exp(-rate_ * dt));
  }

 private:
  double rate_;  // 1/s
};

}  // namespace agent::behaviour
