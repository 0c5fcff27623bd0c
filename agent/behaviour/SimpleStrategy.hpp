// SimpleStrategy (thesis 4.2.2): the segment with the highest utility, its
// centre as the search point. Ties go to the lowest segment number, so the
// choice is deterministic.
#pragma once

#include <memory>

#include "agent/behaviour/FindBallStrategy.hpp"
#include "agent/behaviour/UtilityCalculator.hpp"

namespace agent::behaviour {

class SimpleStrategy : public FindBallStrategy {
 public:
  explicit SimpleStrategy(std::unique_ptr<UtilityCalculator> calc) : calc_(std::move(calc)) {}
  SearchChoice choose(const PositionalDistribution& d, const BehaviourInputs& in) override;

 private:
  std::unique_ptr<UtilityCalculator> calc_;
};

}  // namespace agent::behaviour
