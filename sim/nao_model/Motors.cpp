// The NAO V5 motor table (see Motors.hpp).
#include "sim/nao_model/Motors.hpp"

#include <cmath>

namespace simswift {

namespace {

constexpr double kRpmToRadS = 2.0 * 3.14159265358979323846 / 60.0;

// Aldebaran's NAO V5 (H25) documentation: no-load speed, stall / nominal torque (mN*m).
constexpr MotorType kReMax24{"RE-Max 24", 8000.0, 0.0595, 0.0123};
constexpr MotorType kReMax17{"RE-Max 17", 11900.0, 0.0151, 0.00384};

bool endsWith(const std::string& s, const char* tail) {
  const std::string t(tail);
  return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
}

}  // namespace

double MotorType::torqueConstant() const { return voltage / (no_load_rpm * kRpmToRadS); }
double MotorType::resistance() const { return voltage * torqueConstant() / stall_torque; }

double JointMotor::noLoadSpeed() const { return motor.no_load_rpm * kRpmToRadS / reduction; }
double JointMotor::stallTorque() const { return motor.stall_torque * reduction; }
double JointMotor::nominalTorque() const { return motor.nominal_torque * reduction; }

std::optional<JointMotor> naoJointMotor(const std::string& name) {
  // Type A / type B gearboxes per joint, Aldebaran's NAO V5 (H25) documentation.
  for (const char* j : {"HipYawPitch", "HipRoll", "AnkleRoll"})
    if (endsWith(name, j)) return JointMotor{kReMax24, 201.3};
  for (const char* j : {"HipPitch", "KneePitch", "AnklePitch"})
    if (endsWith(name, j)) return JointMotor{kReMax24, 130.85};
  for (const char* j : {"HeadYaw", "ShoulderPitch", "ElbowYaw"})
    if (endsWith(name, j)) return JointMotor{kReMax17, 150.27};
  for (const char* j : {"HeadPitch", "ShoulderRoll", "ElbowRoll"})
    if (endsWith(name, j)) return JointMotor{kReMax17, 173.22};
  return std::nullopt;
}

}  // namespace simswift
