// The NAO joint servo as the DCM behaves: position control toward the
// commanded angle, torque limited by stiffness (0..1; <= 0 means limp), the
// joint's maximum speed and limits respected. Pure logic, no ODE: RobotBody
// turns its output into ODE motor targets.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace simswift {

struct ServoConfig {
  double kp = 60.0;            // 1/s: velocity target = kp * angle error (before the speed clamp)
  double torque_scale = 1.0;   // multiplies each joint's max_effort
  double limp_damping = 0.02;  // N*m*s/rad of friction left in a limp joint
};

// Counts of commands the servo had to correct; reported at the end of a run.
struct ServoCommandStats {
  int64_t nan_commands = 0;        // NaN/inf angles or stiffnesses (held at the last good value)
  int64_t clamped_angles = 0;      // beyond the joint limits
  int64_t clamped_stiffness = 0;   // outside -1..1
};

class ServoBank {
 public:
  struct Limits { double lower, upper, max_velocity, max_effort; };
  explicit ServoBank(std::vector<Limits> limits = {}, ServoConfig cfg = {});

  // Latch a command (joint-indexed); invalid values are clamped and counted.
  void setTarget(int joint, double angle, double stiffness);
  // Desired joint velocity (rad/s) and torque limit (N*m) for a substep,
  // given the current angle (rad) and the substep length dt (s).
  struct Drive { double velocity; double max_torque; };
  Drive drive(int joint, double angle, double dt) const;

  double target(int joint) const { return target_[joint]; }
  double stiffness(int joint) const { return stiffness_[joint]; }
  const ServoCommandStats& stats() const { return stats_; }
  const ServoConfig& config() const { return cfg_; }

 private:
  std::vector<Limits> limits_;
  std::vector<double> target_, stiffness_;
  ServoConfig cfg_;
  ServoCommandStats stats_;
};

}  // namespace simswift
