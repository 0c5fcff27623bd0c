#include "sim/sensors/Buttons.hpp"

namespace simswift::sensors {

BumperHit bumperFor(const Eigen::Vector3d& point, bool left_foot, double min_x) {
  BumperHit hit;
  if (point.x() < min_x) return hit;
  const double mid = left_foot ? kSoleMidY : -kSoleMidY;
  if (point.y() >= mid)
    hit.left = true;
  else
    hit.right = true;
  return hit;
}

}  // namespace simswift::sensors
