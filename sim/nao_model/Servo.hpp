// The NAO joint servo as the DCM and the motor boards behave: position
// control toward the commanded angle through a geared DC motor whose torque
// falls linearly with speed, limited by a current limit that stiffness
// (0..1; <= 0 means limp) scales and that the DCM lowers when the motor is
// hot. Pure logic, no ODE: RobotBody turns its output into ODE motor targets
// and feeds back the torque the joint really delivered (for current and heat).
//
// Units: rad, rad/s, N*m, A, deg C, s.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace simswift {

struct ServoConfig {
  // Position loop of the motor board: velocity target = kp * angle error
  // (before the speed clamp), i.e. a first-order lag of 1 / kp = 10 ms. With
  // the DCM's one-cycle command delay (10 ms, the runner latches commands for
  // the next tick) a step command shows in the measured angle after about
  // 20 ms: the 2 DCM cycles SPL teams report for the NAO (the thesis, section
  // 3.3.1.2, describes the same one-tick actuation delay on its simulator).
  double kp = 100.0;          // 1/s
  // Gear efficiency: the fraction of the motor torque times the reduction
  // that reaches the joint. Not published; planetary + spur stages of this
  // size are 0.6-0.8 (Aldebaran's NAO V5 (H25) documentation). 0.8 is the upper end: the NAO's
  // type B legs must hold a one-legged 5.3 kg crouch at 210 mm hip height
  // and its get-ups lift the body with them.
  double gear_efficiency = 0.8;
  // The DC motor's torque-speed line (torque = stall at rest, 0 at the
  // no-load speed). false: a hard velocity motor capped at the stall torque
  // (the servo before the motor model; kept for comparisons).
  bool torque_speed_line = true;
  double torque_scale = 1.0;   // multiplies every joint's torque (tests)
  double limp_damping = 0.02;  // N*m*s/rad of friction left in a limp joint
  // Floor (kg*m^2) on every link's principal moments of inertia, applied when
  // RobotBody builds the ODE bodies. Physically the reflected rotor inertia
  // (armature) of the geared joint motors, which the bare link inertias
  // leave out; numerically it keeps the NAO's small 70-130 g links from
  // blowing up ODE's iterative solver (measured: QuickStep with 20 iterations at 5 ms blows a bare NAO-like model up). 0 disables it.
  double min_link_inertia = 5e-4;

  // --- Heat. One thermal mass per motor: C dT/dt = I^2 R - (T - ambient) / R_th.
  // Chosen so the continuous (nominal) current settles near 70 deg C, the
  // temperature at which NAO legs start to be limited in matches, over
  // minutes (Maxon gives ~10-20 s winding and ~10 min motor time constants
  // for these sizes; one lumped 300 s constant is between).
  double ambient_temperature = 27.0;    // deg C
  double thermal_resistance = 20.0;     // K/W, winding to air
  double thermal_time_constant = 300.0; // s
  // The DCM's current limit falls linearly from 100 % at hot_start to
  // hot_min_fraction at hot_end (and stays there above).
  double hot_start = 70.0;              // deg C
  double hot_end = 90.0;                // deg C
  double hot_min_fraction = 0.2;
};

// Counts of commands the servo had to correct; reported at the end of a run.
struct ServoCommandStats {
  int64_t nan_commands = 0;        // NaN/inf angles or stiffnesses (held at the last good value)
  int64_t clamped_angles = 0;      // beyond the joint limits
  int64_t clamped_stiffness = 0;   // outside -1..1
};

class ServoBank {
 public:
  // One joint's range and motor. max_velocity is the no-load speed (rad/s)
  // and max_effort the stall torque (N*m), both joint side before gear
  // losses. torque_constant (N*m/A, motor side) and resistance (ohm) give
  // current and heat; reduction 0 = no electrical model (current 0, ambient).
  struct Limits {
    double lower, upper, max_velocity, max_effort;
    double reduction = 0, torque_constant = 0, resistance = 0;
  };
  explicit ServoBank(std::vector<Limits> limits = {}, ServoConfig cfg = {});

  // Latch a command (joint-indexed); invalid values are clamped and counted.
  void setTarget(int joint, double angle, double stiffness);
  // The motor for a substep, given the current angle (rad) and the substep
  // length dt (s): it pushes with torque = (velocity - joint speed) /
  // compliance, capped at max_torque (the current limit). velocity is the
  // duty cycle as a speed (rad/s, at most no-load), compliance = no-load
  // speed / stall torque (rad/s per N*m): the torque-speed line. Limp:
  // compliance 0 (a hard velocity-0 row) with a small cap = friction.
  struct Drive { double velocity; double max_torque; double compliance; };
  Drive drive(int joint, double angle, double dt) const;
  // After a substep of dt s in which the joint delivered `torque` (N*m):
  // the motor current and the winding temperature.
  void heat(int joint, double torque, double dt);

  // Makes `joint` follow `leader` (target * multiplier, same stiffness), for
  // joints sharing one motor (RHipYawPitch). Not counted in stats().
  void follow(int joint, int leader, double multiplier);

  double target(int joint) const { return target_[joint]; }
  double stiffness(int joint) const { return stiffness_[joint]; }
  double current(int joint) const { return current_[joint]; }          // A, motor
  double temperature(int joint) const { return temperature_[joint]; }  // deg C
  void setTemperature(int joint, double t) { temperature_[joint] = t; }
  // Fraction (0..1) of the current limit the DCM allows at this temperature.
  double thermalLimit(int joint) const;
  const ServoCommandStats& stats() const { return stats_; }
  const ServoConfig& config() const { return cfg_; }
  const Limits& limits(int joint) const { return limits_[joint]; }

 private:
  std::vector<Limits> limits_;
  std::vector<double> target_, stiffness_, current_, temperature_;
  ServoConfig cfg_;
  ServoCommandStats stats_;
};

}  // namespace simswift
