// BallDistributionGenerator (thesis 4.2): the interface of everything that
// turns the robot's inputs into a PositionalDistribution of the ball.
#pragma once

#include "agent/behaviour/BehaviourInputs.hpp"
#include "agent/behaviour/PositionalDistribution.hpp"

namespace agent::behaviour {

class BallDistributionGenerator {
 public:
  virtual ~BallDistributionGenerator() = default;
  // Fold in this tick's inputs; dt = s since the previous update (0 on the
  // first). Returns the updated distribution.
  virtual const PositionalDistribution& update(const BehaviourInputs& in, double dt) = 0;
  virtual const PositionalDistribution& distribution() const = 0;
  // This robot's own estimate, the one sent to teammates. For a local
  // generator it is distribution() itself.
  virtual const PositionalDistribution& localDistribution() const { return distribution(); }
};

}  // namespace agent::behaviour
