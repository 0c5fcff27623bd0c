#include "sim/sensors/Imu.hpp"

#include <algorithm>
#include <cmath>

namespace simswift::sensors {

Eigen::Vector2d torsoRollPitch(const Eigen::Matrix3d& r) {
  // Row 2 of R holds the world-z components of the torso's axes.
  const double roll = std::asin(std::clamp(r(2, 1), -1.0, 1.0));
  const double pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  return {roll, pitch};
}

Eigen::Vector3d naoAccelerometer(const Eigen::Matrix3d& torso_to_world,
                                 const Eigen::Vector3d& a_world, double gravity) {
  const Eigen::Vector3d g_world(0, 0, -gravity);
  return torso_to_world.transpose() * (g_world - a_world);
}

ImuTruth ImuModel::update(const Eigen::Matrix3d& torso_to_world, const Eigen::Vector3d& omega_world,
                          const Eigen::Vector3d& point_velocity_world, double dt, double gravity) {
  if (!has_history_) reset(torso_to_world, point_velocity_world);
  ImuTruth t;
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

  t.accel = naoAccelerometer(torso_to_world, a_world, gravity);
  const Eigen::Vector2d rp = torsoRollPitch(torso_to_world);
  t.angle_x = rp.x();
  t.angle_y = rp.y();
  return t;
}

}  // namespace simswift::sensors
