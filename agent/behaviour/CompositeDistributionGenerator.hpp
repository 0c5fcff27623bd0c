// CompositeDistributionGenerator (thesis 4.2.1.1): the local distribution,
// updated each tick by its DistributionComponents in the order given.
#pragma once

#include <memory>
#include <vector>

#include "agent/behaviour/BallDistributionGenerator.hpp"
#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/behaviour/DistributionComponent.hpp"

namespace agent::behaviour {

class CompositeDistributionGenerator : public BallDistributionGenerator {
 public:
  CompositeDistributionGenerator(PositionalDistribution initial,
                                 std::vector<std::unique_ptr<DistributionComponent>> components);
  // The thesis's five components, in this order: PenalisedComponent and
  // FlipFilterComponent first (a reset discards stale history before this
  // tick's evidence is added), EntropyComponent (decay of old evidence),
  // then this tick's evidence: BallPosComponent, RobotPosComponent.
  static std::unique_ptr<CompositeDistributionGenerator> makeDefault(const BehaviourConfig& c);

  const PositionalDistribution& update(const BehaviourInputs& in, double dt) override;
  const PositionalDistribution& distribution() const override { return dist_; }
  const std::vector<std::unique_ptr<DistributionComponent>>& components() const {
    return components_;
  }

 private:
  PositionalDistribution dist_;
  std::vector<std::unique_ptr<DistributionComponent>> components_;
};

}  // namespace agent::behaviour
