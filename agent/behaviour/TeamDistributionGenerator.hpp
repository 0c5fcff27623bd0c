// TeamDistributionGenerator (thesis 4.2.1.2): combines this robot's local
// distribution with the local distributions its teammates send:
//   P(D_j) = P(S_j) x sum_{n=1..N} P(R_nj),   then normalised,
// where S is this robot's local distribution and the sum runs over all N
// robots heard, this robot included. Multiplying by the local P(S_j)
// weights the robot's own estimate more heavily.
#pragma once

#include <memory>

#include "agent/behaviour/BallDistributionGenerator.hpp"

namespace agent::behaviour {

class TeamDistributionGenerator : public BallDistributionGenerator {
 public:
  // teammate_timeout: s; a teammate heard longer ago is left out of the sum.
  TeamDistributionGenerator(std::unique_ptr<BallDistributionGenerator> local,
                            double teammate_timeout);

  const PositionalDistribution& update(const BehaviourInputs& in, double dt) override;
  const PositionalDistribution& distribution() const override { return team_; }
  const PositionalDistribution& localDistribution() const override {
    return local_->distribution();
  }
  int robotsCombined() const { return robots_; }  // N of the last update

 private:
  std::unique_ptr<BallDistributionGenerator> local_;
  double timeout_;
  PositionalDistribution team_;
  int robots_ = 1;
};

}  // namespace agent::behaviour
