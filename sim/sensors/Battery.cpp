#include "sim/sensors/Battery.hpp"

#include <algorithm>

namespace simswift::sensors {

void Battery::step(double dt) {
  charge_ = std::clamp(charge_ + current_ * dt / (capacity_ah_ * 3600.0), 0.0, 1.0);
}

}  // namespace simswift::sensors
