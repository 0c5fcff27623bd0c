// ServoBank: the DCM-like joint position servo (see Servo.hpp).
#include "sim/nao_model/Servo.hpp"

#include <algorithm>
#include <cmath>

namespace simswift {

namespace {
constexpr double kSilentClamp = 1e-6;  // rad, well above float rounding near pi
}  // namespace

ServoBank::ServoBank(std::vector<Limits> limits, ServoConfig cfg)
    : limits_(std::move(limits)), cfg_(cfg) {
  target_.resize(limits_.size());
  stiffness_.assign(limits_.size(), 0.0);  // limp until commanded, like a NAO at boot
  for (size_t j = 0; j < limits_.size(); ++j)
    target_[j] = std::clamp(0.0, limits_[j].lower, limits_[j].upper);
}

void ServoBank::setTarget(int joint, double angle, double stiffness) {
  const Limits& lim = limits_[joint];
  // A NaN/inf field keeps the last good value of that field only.
  if (!std::isfinite(angle) || !std::isfinite(stiffness)) ++stats_.nan_commands;
  if (std::isfinite(angle)) {
    if (angle < lim.lower || angle > lim.upper) {
      // Within float rounding of a limit (commands arrive as float) is not
      // worth reporting.
      if (angle < lim.lower - kSilentClamp || angle > lim.upper + kSilentClamp) ++stats_.clamped_angles;
      angle = std::clamp(angle, lim.lower, lim.upper);
    }
    target_[joint] = angle;
  }
  if (std::isfinite(stiffness)) {
    if (stiffness < -1.0 || stiffness > 1.0) {
      ++stats_.clamped_stiffness;
      stiffness = std::clamp(stiffness, -1.0, 1.0);
    }
    stiffness_[joint] = stiffness;
  }
}

void ServoBank::follow(int joint, int leader, double multiplier) {
  const Limits& lim = limits_[joint];
  target_[joint] = std::clamp(target_[leader] * multiplier, lim.lower, lim.upper);
  stiffness_[joint] = stiffness_[leader];
}

ServoBank::Drive ServoBank::drive(int joint, double angle, double dt) const {
  const Limits& lim = limits_[joint];
  const double s = stiffness_[joint];
  if (!(s > 0)) {
    // Limp: the motor does not drive, but the gearbox still resists motion
    // a little (velocity target 0 with a small torque cap = friction).
    return {0.0, cfg_.limp_damping * lim.max_velocity};
  }
  const double error = target_[joint] - angle;  // rad
  double v = cfg_.kp * error;                    // rad/s
  v = std::clamp(v, -lim.max_velocity, lim.max_velocity);
  // Never ask for more than reaches the target in this substep, so a stiff
  // servo does not overshoot because of the discrete step.
  if (dt > 0) {
    const double reach = std::abs(error) / dt;
    v = std::clamp(v, -reach, reach);
  }
  return {v, s * lim.max_effort * cfg_.torque_scale};
}

}  // namespace simswift
