// FindBall class (thesis 4.2): each tick, forwards the robot's inputs to its
// BallDistributionGenerator, hands the resulting distribution to its
// FindBallStrategy and publishes the suggested search point (FindBallResult,
// the Blackboard's "findball" section once Behaviour is on the Blackboard).
// Either part may be absent: no generator keeps a uniform distribution, no
// strategy makes no suggestion.
#pragma once

#include <memory>

#include "agent/behaviour/BallDistributionGenerator.hpp"
#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/behaviour/FindBallStrategy.hpp"

namespace agent::behaviour {

struct FindBallResult {
  PositionalDistribution distribution;  // the generator's (team) distribution
  PositionalDistribution local;         // this robot's local one (sent to teammates)
  SearchChoice choice;                  // the strategy's suggestion this tick
};

class FindBall {
 public:
  FindBall(std::unique_ptr<BallDistributionGenerator> generator,
           std::unique_ptr<FindBallStrategy> strategy, PositionalDistribution initial = {});
  // The thesis's configuration: TeamDistributionGenerator over a
  // CompositeDistributionGenerator; SimpleStrategy over a
  // DistributedUtilityCalculator (over SimpleUtilityCalculator), or the
  // SimpleUtilityCalculator alone if strategy.distributed is false.
  static std::unique_ptr<FindBall> makeDefault(const BehaviourConfig& c);

  const FindBallResult& tick(const BehaviourInputs& in);
  const FindBallResult& result() const { return result_; }

 private:
  std::unique_ptr<BallDistributionGenerator> generator_;
  std::unique_ptr<FindBallStrategy> strategy_;
  FindBallResult result_;
  double last_time_ = 0;
  bool first_ = true;
};

}  // namespace agent::behaviour
