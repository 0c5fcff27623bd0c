#include "agent/behaviour/SonarFilter.hpp"

#include <algorithm>
#include <cmath>

namespace agent::behaviour {

void SonarFilter::step(int side, double echo) {
  const int lo = -static_cast<int>(std::lround(c_.sonar_min_frames));
  const int hi = static_cast<int>(std::lround(c_.sonar_hold_frames));
  int& n = count_[side];
  if (echo < c_.sonar_near_distance)
    n = n == 0 ? hi : n + 1;
  else
    n = n - 1;
  n = std::clamp(n, lo, hi);
}

SonarState SonarFilter::update(double left, double right) {
  step(0, left);
  step(1, right);
  SonarState s;
  s.left = left;
  s.right = right;
  s.near_left = count_[0] > 0;
  s.near_right = count_[1] > 0;
  return s;
}

}  // namespace agent::behaviour
