// The NAO V5's joint motors: the one home for motor types, reductions and
// the electrical figures the motor model needs (Aldebaran's NAO V5 (H25) documentation, from
// Aldebaran's hardware documentation; V4 and V5 share them).
//
// Joint-side figures follow from the motor and the reduction N:
//   no-load speed (rad/s) = motor no-load speed / N
//   stall torque (N*m)    = motor stall torque * N   (before gear losses)
// The URDF's <limit velocity effort> carry the same two joint-side figures
// for every other consumer (tests/nao_model checks they agree).
//
// Electrical figures are not published per joint. They follow from the
// motor data with one assumption: a 12 V winding (Maxon's RE-max 17 / 24
// catalogue windings; the NAO's motor boards regulate the 21.6 V battery
// down). Then torque constant k_t = V / no-load speed (SI: N*m/A = V*s/rad)
// and terminal resistance R = V / stall current = V * k_t / stall torque.
#pragma once

#include <optional>
#include <string>

namespace simswift {

struct MotorType {
  const char* name;
  double no_load_rpm;          // motor shaft, at the nominal voltage
  double stall_torque;         // N*m, motor shaft
  double nominal_torque;       // N*m, motor shaft, continuous
  double voltage = 12.0;       // V, the winding assumed (see above)
  double torqueConstant() const;   // N*m/A
  double resistance() const;       // ohm
};

// A joint's motor and reduction.
struct JointMotor {
  MotorType motor;
  double reduction;            // motor turns per joint turn
  double noLoadSpeed() const;  // rad/s at the joint
  double stallTorque() const;  // N*m at the joint, before gear losses
  double nominalTorque() const;  // N*m at the joint, continuous, before gear losses
};

// The motor behind a NAO joint (model joint name, e.g. "LKneePitch"), or
// nothing for joints whose motor is not published (WristYaw, Hand).
std::optional<JointMotor> naoJointMotor(const std::string& joint_name);

}  // namespace simswift
