// Joint readings: encoder angles, motor temperatures and currents.
//
// - Angle: the model joint angle (rad) plus optional noise, rounded to the
//   encoder step (SensorConfig::encoder_step, 12-bit: 2 pi / 4096 rad).
//   The Hand slots read 0..1 (fraction open) as libagent expects, mapped
//   linearly from the joint's limits.
// - Temperature (deg C) and current (A): the motor model's own figures
//   (sim/nao_model/Servo.hpp: I^2 R heating, the DCM's hot derating), copied
//   by SensorSuite; the motor is where they act, so they live there.
#pragma once

namespace simswift::sensors {

// Model angle (rad) to the libagent reading: hands as 0..1, others in rad.
double encoderValue(double angle, bool is_hand, double lower, double upper);

}  // namespace simswift::sensors
