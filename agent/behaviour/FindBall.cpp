#include "agent/behaviour/FindBall.hpp"

#include <algorithm>

#include "agent/behaviour/CompositeDistributionGenerator.hpp"
#include "agent/behaviour/DistributedUtilityCalculator.hpp"
#include "agent/behaviour/SimpleStrategy.hpp"
#include "agent/behaviour/SimpleUtilityCalculator.hpp"
#include "agent/behaviour/TeamDistributionGenerator.hpp"

namespace agent::behaviour {

FindBall::FindBall(std::unique_ptr<BallDistributionGenerator> generator,
                   std::unique_ptr<FindBallStrategy> strategy, PositionalDistribution initial)
    : generator_(std::move(generator)),
      strategy_(std::move(strategy)),
      result_{generator_ ? generator_->distribution() : initial,
              generator_ ? generator_->localDistribution() : initial,
              {}} {}

std::unique_ptr<FindBall> FindBall::makeDefault(const BehaviourConfig& c) {
  auto team = std::make_unique<TeamDistributionGenerator>(
      CompositeDistributionGenerator::makeDefault(c), c.strategy.teammate_timeout);
  std::unique_ptr<UtilityCalculator> calc = std::make_unique<SimpleUtilityCalculator>(c.strategy);
  if (c.strategy.distributed)
    calc = std::make_unique<DistributedUtilityCalculator>(std::move(calc), c.strategy);
  return std::make_unique<FindBall>(std::move(team),
                                    std::make_unique<SimpleStrategy>(std::move(calc)));
}

const FindBallResult& FindBall::tick(const BehaviourInputs& in) {
  const double dt = first_ ? 0.0 : std::max(0.0, in.time - last_time_);
  first_ = false;
  last_time_ = in.time;
  if (generator_) {
    result_.distribution = generator_->update(in, dt);
    result_.local = generator_->localDistribution();
  }
  result_.choice = strategy_ ? strategy_->choose(result_.distribution, in) : SearchChoice{};
  return result_;
}

}  // namespace agent::behaviour
