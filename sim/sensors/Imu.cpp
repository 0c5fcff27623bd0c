#include "sim/sensors/Imu.hpp"

#include <algorithm>
#include <cmath>

#include "common/libagent/Inertial.hpp"

namespace simswift::sensors {

namespace la = common::libagent;

Eigen::Vector2d torsoRollPitch(const Eigen::Matrix3d& r) {
  // Row 2 of R holds the world-z components of the torso's axes.
  const double roll = std::asin(std::clamp(r(2, 1), -1.0, 1.0));
  const double pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  return {roll, pitch};
}

Eigen::Vector3d specificForce(const Eigen::Matrix3d& torso_to_world, const Eigen::Vector3d& a_world,
                              double gravity) {
  const Eigen::Vector3d g_world(0, 0, -gravity);
  return torso_to_world.transpose() * (a_world - g_world);
}

void writeV5InertialSlots(const ImuSample& m, int gyr_raw_sign, int acc_raw_sign, float* s) {
  namespace S = la::Sensors;
  namespace in = la::inertial;
  // The calibrated values (rad/s, m/s^2) with the V5's signs.
  double gyroscope[3], accelerometer[3];
  for (int k = 0; k < 3; ++k) {
    gyroscope[k] = in::kGyroscopeSign[k] * m.gyro[k];
    accelerometer[k] = in::kAccelerometerSign[k] * m.specific_force[k];
  }
  for (int k = 0; k < 3; ++k) {
    s[S::InertialSensor_GyroscopeX + k] = static_cast<float>(gyroscope[k]);
    s[S::InertialSensor_AccelerometerX + k] = static_cast<float>(accelerometer[k]);
    // The legacy raw accelerometer (counts) beside the m/s^2 values.
    s[S::InertialSensor_AccX + k] =
        static_cast<float>(acc_raw_sign * in::kAccCountsPerMetrePerSecondSquared * accelerometer[k]);
  }
  // The legacy raw gyrometer (counts): X and Y only, as on every NAO.
  s[S::InertialSensor_GyrX] = static_cast<float>(gyr_raw_sign * in::kGyrCountsPerRadPerSecond * gyroscope[0]);
  s[S::InertialSensor_GyrY] = static_cast<float>(gyr_raw_sign * in::kGyrCountsPerRadPerSecond * gyroscope[1]);
  s[S::InertialSensor_GyrRef] = 0.0f;
  s[S::InertialSensor_AngleX] = static_cast<float>(m.angle_x);
  s[S::InertialSensor_AngleY] = static_cast<float>(m.angle_y);
}

ImuSample ImuModel::update(const Eigen::Matrix3d& torso_to_world, const Eigen::Vector3d& omega_world,
                           const Eigen::Vector3d& point_velocity_world, double dt, double gravity) {
  if (!has_history_) reset(torso_to_world, point_velocity_world);
  ImuSample t;
  Eigen::Vector3d a_world = Eigen::Vector3d::Zero();
  if (dt > 0) a_world = (point_velocity_world - prev_velocity_) / dt;
  if (primed_ && dt > 0) {
    // Mean angular velocity over the tick, in torso axes (the body-frame
    // rotation R_prev^T R_now). The angle-axis form is exact for any
    // rotation below pi per tick (314 rad/s).
    const Eigen::AngleAxisd delta(prev_rotation_.transpose() * torso_to_world);
    t.gyro = delta.axis() * (delta.angle() / dt);
  } else {
    t.gyro = torso_to_world.transpose() * omega_world;
  }
  prev_rotation_ = torso_to_world;
  prev_velocity_ = point_velocity_world;
  primed_ = true;

  t.specific_force = specificForce(torso_to_world, a_world, gravity);
  const Eigen::Vector2d rp = torsoRollPitch(torso_to_world);
  t.angle_x = rp.x();
  t.angle_y = rp.y();
  return t;
}

}  // namespace simswift::sensors
