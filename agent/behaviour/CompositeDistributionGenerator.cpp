#include "agent/behaviour/CompositeDistributionGenerator.hpp"

#include "agent/behaviour/BallPosComponent.hpp"
#include "agent/behaviour/EntropyComponent.hpp"
#include "agent/behaviour/FlipFilterComponent.hpp"
#include "agent/behaviour/PenalisedComponent.hpp"
#include "agent/behaviour/RobotPosComponent.hpp"

namespace agent::behaviour {

CompositeDistributionGenerator::CompositeDistributionGenerator(
    PositionalDistribution initial, std::vector<std::unique_ptr<DistributionComponent>> components)
    : dist_(std::move(initial)), components_(std::move(components)) {}

std::unique_ptr<CompositeDistributionGenerator> CompositeDistributionGenerator::makeDefault(
    const BehaviourConfig& c) {
  std::vector<std::unique_ptr<DistributionComponent>> comps;
  comps.push_back(std::make_unique<PenalisedComponent>());
  comps.push_back(std::make_unique<FlipFilterComponent>(c.distribution.flip_min_confidence));
  comps.push_back(std::make_unique<EntropyComponent>(c.distribution.entropy_rate));
  comps.push_back(std::make_unique<BallPosComponent>(c.distribution.ball_pos_rate));
  comps.push_back(std::make_unique<RobotPosComponent>(c.distribution.robot_pos_rate));
  return std::make_unique<CompositeDistributionGenerator>(
      PositionalDistribution::fromConfig(c.grid, c.field), std::move(comps));
}

const PositionalDistribution& CompositeDistributionGenerator::update(const BehaviourInputs& in,
                                                                     double dt) {
  for (auto& comp : components_) comp->apply(dist_, in, dt);
  return dist_;
}

}  // namespace agent::behaviour
