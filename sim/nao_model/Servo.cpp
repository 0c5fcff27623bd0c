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
  current_.assign(limits_.size(), 0.0);
  temperature_.assign(limits_.size(), cfg_.ambient_temperature);
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

double ServoBank::thermalLimit(int joint) const {
  const double t = temperature_[joint];
  if (t <= cfg_.hot_start) return 1.0;
  if (t >= cfg_.hot_end) return cfg_.hot_min_fraction;
  const double u = (t - cfg_.hot_start) / (cfg_.hot_end - cfg_.hot_start);
  return 1.0 - u * (1.0 - cfg_.hot_min_fraction);
}

ServoBank::Drive ServoBank::drive(int joint, double angle, double dt) const {
  const Limits& lim = limits_[joint];
  const double s = stiffness_[joint];
  if (!(s > 0)) {
    // Limp: the motor does not drive, but the gearbox still resists motion
    // a little (velocity target 0 with a small torque cap = friction).
    return {0.0, cfg_.limp_damping * lim.max_velocity, 0.0};
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
  // The motor as a DC motor driven at duty v / no-load speed: torque =
  // b (v - w) with b = stall / no-load speed (the back-EMF's slope), so at
  // full duty it runs along the torque-speed line from stall at rest to 0 at
  // no-load speed. RobotBody gives ODE 1 / b as the motor row's CFM, which
  // makes that line implicit (stable for any link inertia). The motor
  // board's current limit (stiffness x the DCM's thermal derating) caps the
  // torque at any speed. Joint side, after gear losses (efficiency).
  const double stall = lim.max_effort * cfg_.gear_efficiency * cfg_.torque_scale;
  const double max_torque = std::min(1.0, s) * thermalLimit(joint) * stall;
  return {v, max_torque, cfg_.torque_speed_line ? lim.max_velocity / stall : 0.0};
}

void ServoBank::heat(int joint, double torque, double dt) {
  const Limits& lim = limits_[joint];
  if (!(lim.reduction > 0) || !(lim.torque_constant > 0)) {
    current_[joint] = 0;
    return;
  }
  // Motor torque = joint torque / (reduction x efficiency); current = that / k_t.
  const double i = std::abs(torque) / (lim.reduction * cfg_.gear_efficiency * lim.torque_constant);
  current_[joint] = i;
  // C dT/dt = I^2 R - (T - ambient) / R_th, with C = time constant / R_th;
  // exact for a constant current over dt.
  const double t_inf = cfg_.ambient_temperature + i * i * lim.resistance * cfg_.thermal_resistance;
  const double k = 1.0 - std::exp(-dt / cfg_.thermal_time_constant);
  temperature_[joint] += (t_inf - temperature_[joint]) * k;
}

}  // namespace simswift
