// Joint readings: encoder angles, motor temperatures and currents.
//
// - Angle: the model joint angle (rad) plus optional noise, rounded to the
//   encoder step (SensorConfig::encoder_step, 12-bit: 2 pi / 4096 rad).
//   The Hand slots read 0..1 (fraction open) as libagent expects, mapped
//   linearly from the joint's limits.
// - Temperature (deg C): first-order lag toward
//   ambient + temperature_per_torque * |torque| with time constant
//   temperature_time_constant. Coarse, but it rises with load over minutes,
//   like the NAO's leg motors, and never changes by a visible amount per tick.
// - Current (A): idle_current + |torque| / torque_per_amp.
#pragma once

namespace simswift::sensors {

struct SensorConfig;

// One thermal step of length dt (s) for a joint at temperature `t` (deg C)
// holding |torque| (N*m); exact discretisation of the first-order lag.
double temperatureStep(double t, double abs_torque, double dt, const SensorConfig& cfg);

double jointCurrent(double torque, const SensorConfig& cfg);

// Model angle (rad) to the libagent reading: hands as 0..1, others in rad.
double encoderValue(double angle, bool is_hand, double lower, double upper);

}  // namespace simswift::sensors
