// FlipFilterComponent: a mislocalised robot's field-frame history is wrong
// (possibly mirrored), so on a detected flip (or confidence below
// min_confidence, if set) the distribution goes back to uniform.
#pragma once

#include "agent/behaviour/DistributionComponent.hpp"

namespace agent::behaviour {

class FlipFilterComponent : public DistributionComponent {
 public:
  explicit FlipFilterComponent(double min_confidence = 0.0) : min_confidence_(min_confidence) {}
  const char* name() const override { return "FlipFilterComponent"; }
  void apply(PositionalDistribution& d, const BehaviourInputs& in, double) override {
    if (in.self.flipped || (min_confidence_ > 0 && in.self.confidence < min_confidence_)) d.reset();
  }

 private:
  double min_confidence_;  // 0..1, 0 = flip signal only
};

}  // namespace agent::behaviour
