#include "sim/sensors/JointEncoders.hpp"

#include <algorithm>
#include <cmath>


namespace simswift::sensors {

double encoderValue(double angle, bool is_hand, double lower, double upper) {
  if (!is_hand) return angle;
  if (!(upper > lower)) return angle;
  return std::clamp((angle - lower) / (upper - lower), 0.0, 1.0);
}

}  // namespace simswift::sensors
