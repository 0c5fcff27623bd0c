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
  // Floor (kg*m^2) on every link's principal moments of inertia, applied when
  // RobotBody builds the ODE bodies. Physically the reflected rotor inertia
  // (armature) of the geared joint motors, which the bare link inertias
  // leave out; numerically it keeps the NAO's small 70-130 g links from
  // blowing up ODE's iterative solver (facts.md section 7). 0 disables it.
  double min_link_inertia = 5e-4;
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

  // Makes `joint` follow `leader` (target * multiplier, same stiffness), for
  // joints sharing one motor (RHipYawPitch). Not counted in stats().
  void follow(int joint, int leader, double multiplier);

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
