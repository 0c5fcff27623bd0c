// The NAO V5's inertial slots as a libagent client reads them (NAOqi 2.1
// DCM keys InertialSensor/...): units, signs and scales, and the readers the
// robot code uses. The one home of these facts: the simulator writes the
// slots with them (sim/sensors/Imu.cpp, writeV5InertialSlots), the robot code reads them
// back here, and docs/libagent.md ("Inertial sensors") lists them with their
// sources.
//
// Physical quantities are in the NAO torso axes (x forward, y left, z up),
// right-handed:
//   body rate   w (rad/s): +x = rolling to the robot's right (left side up),
//               +y = pitching forward, +z = turning anti-clockwise (left)
//               seen from above;
//   specific force f (m/s^2): what an ideal accelerometer measures, the
//               acceleration minus gravity: (0, 0, +9.81) upright at rest,
//               0 in free fall.
//
// Slot by slot on the V5:
//   GyroscopeX/Y = +w.x, +w.y rad/s. B-Human's V5-era NaoProvider (DCM)
//                  reads them unchanged into its right-handed frame.
//   GyroscopeZ   = -w.z rad/s: anti-clockwise yaw reads NEGATIVE on the V5.
//                  rUNSWift 2017/2018 MotionOdometry multiplies it by -0.01
//                  (one 10 ms frame) for a turn "in the same direction as"
//                  the walk's anti-clockwise-positive turn; B-Human's V5
//                  provider negates it ("negated for some reason"). The V6
//                  reverses this.
//   AccelerometerX/Y/Z = -f.x, +f.y, -f.z m/s^2 (B-Human's V5 provider
//                  reads acc = (-X, +Y, -Z) into its specific-force frame):
//                  upright at rest AccelerometerZ = -9.81, leaning forward
//                  AccelerometerX > 0, leaning right AccelerometerY > 0.
//   AngleX/AngleY = torso roll and pitch, rad, right-handed: leaning right
//                  AngleX > 0, leaning forward AngleY > 0 (rUNSWift's
//                  safety skill: AngleY beyond +FALLEN_ANG = fallen forward,
//                  beyond -FALLEN_ANG = on the back). The inertial board's
//                  fused estimate.
//   GyrX/GyrY    = the legacy raw gyrometer values in counts (Aldebaran's
//                  1.14 page lists them under raw data; one old mirrored page
//                  says rad/s): kGyrCountsPerRadPerSecond per rad/s.
//   GyrRef       = 0 (the raw reference; no client reads it).
//   AccX/Y/Z     = the legacy raw accelerometer values in counts:
//                  kAccCountsPerMetrePerSecondSquared per m/s^2 of the
//                  Accelerometer values.
// The sign of the raw values against the calibrated ones is not settled by a
// public source. simswift writes them with the same sign by default
// (SensorConfig::gyr_raw_sign / acc_raw_sign, sim/sensors/SensorConfig.hpp):
// rUNSWift's V5 walk adds the converted GyrY / 25 to the ankle pitch, and its
// V6 walk adds GyroscopeY (same sign as the V5's, only Z flips) in the same
// place with the same sign, which suggests GyrY and GyroscopeY agree; rUNSWift
// copies AccelerometerX/Y/Z into its AccX/Y/Z before filtering. The robot
// code in agent/ reads only the calibrated values, so it is right under
// either setting.
#pragma once

#include "common/libagent/AgentShared.hpp"

namespace common::libagent::inertial {

// slot = sign * physical quantity (and physical = sign * slot: the signs are
// +-1, so both ways are exact in floating point).
constexpr double kGyroscopeSign[3] = {+1.0, +1.0, -1.0};      // GyroscopeX/Y/Z vs w
constexpr double kAccelerometerSign[3] = {-1.0, +1.0, -1.0};  // AccelerometerX/Y/Z vs f

// rUNSWift 2017/2018 FilteredTouch: rad/s = DEG2RAD(GyrX) / 2.35, so 2.35
// counts per deg/s = 134.6 counts per rad/s. This figure rather than
// B-Human's older 1600/12 = 133.3: simswift serves rUNSWift's libagent, and
// with it an unchanged FilteredTouch reads the true rate.
constexpr double kGyrCountsPerRadPerSecond = 2.35 * 180.0 / 3.14159265358979323846;
// rUNSWift 2017/2018 FilteredTouch's (unused) ACC_SCALE 9.81 / 65: 65 counts
// per g.
constexpr double kAccCountsPerMetrePerSecondSquared = 65.0 / 9.81;

// Body rates w (rad/s, right-handed torso axes) from GyroscopeX/Y/Z.
struct BodyRates {
  double x = 0, y = 0, z = 0;
};
inline BodyRates bodyRates(const float* sensors) {
  namespace S = Sensors;
  return {kGyroscopeSign[0] * sensors[S::InertialSensor_GyroscopeX],
          kGyroscopeSign[1] * sensors[S::InertialSensor_GyroscopeY],
          kGyroscopeSign[2] * sensors[S::InertialSensor_GyroscopeZ]};
}

}  // namespace common::libagent::inertial
