#include "sim/sensors/JointEncoders.hpp"

#include <algorithm>
#include <cmath>

#include "sim/sensors/SensorConfig.hpp"

namespace simswift::sensors {

double temperatureStep(double t, double abs_torque, double dt, const SensorConfig& cfg) {
  const double target = cfg.ambient_temperature + cfg.temperature_per_torque * abs_torque;
  const double k = 1.0 - std::exp(-dt / cfg.temperature_time_constant);
  return t + (target - t) * k;
}

double jointCurrent(double torque, const SensorConfig& cfg) {
  return cfg.idle_current + std::abs(torque) / cfg.torque_per_amp;
}

double encoderValue(double angle, bool is_hand, double lower, double upper) {
  if (!is_hand) return angle;
  if (!(upper > lower)) return angle;
  return std::clamp((angle - lower) / (upper - lower), 0.0, 1.0);
}

}  // namespace simswift::sensors
