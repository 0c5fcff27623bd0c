// FindBallStrategy (thesis 4.2): given the ball distribution, suggest where
// to search (the thesis's AbsCoord; here the segment and its point).
#pragma once

#include <vector>

#include "agent/behaviour/BehaviourInputs.hpp"
#include "agent/behaviour/PositionalDistribution.hpp"

namespace agent::behaviour {

struct SearchChoice {
  int segment = -1;               // 0-based; -1 = no suggestion
  Point2 point;                   // field mm
  std::vector<double> utilities;  // per segment, if the strategy has them
};

class FindBallStrategy {
 public:
  virtual ~FindBallStrategy() = default;
  virtual SearchChoice choose(const PositionalDistribution& d, const BehaviourInputs& in) = 0;
};

}  // namespace agent::behaviour
