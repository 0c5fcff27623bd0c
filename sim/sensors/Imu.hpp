// The NAO's torso inertial board: gyrometer, accelerometer and the board's
// fused torso angles. Pure maths here; SensorSuite feeds it the torso state
// and adds noise.
//
// ImuModel measures in physical terms, right-handed in the NAO torso axes
// (x forward, y left, z up):
// - gyro: torso angular velocity, rad/s, averaged over the tick: the
//   rotation vector of R_prev^T R_now divided by the tick. Like the
//   accelerometer's velocity difference, this is what a sensor integrating
//   over its 10 ms sample sees, and it leaves out the solver's within-step
//   velocity corrections that ODE's instantaneous body velocity carries (on a
//   standing robot those are ~0.05 rad/s RMS).
// - specific_force: what an ideal accelerometer measures, the IMU point's
//   acceleration minus gravity, R^T (a_world - g_world) with g_world =
//   (0, 0, -9.81) m/s^2: (0, 0, +9.81) upright at rest, 0 in free fall.
// - angle_x (roll) and angle_y (pitch), rad: the tilt of the torso as an
//   accelerometer-fused board sees it, i.e. the elevations of the torso's
//   axes above the horizontal plane:
//     angle_y = asin(-R(2,0))  (x axis pointing down = pitched forward),
//     angle_x = asin( R(2,1))  (y axis, the left side, pointing up = rolled right).
//   angle_y equals the Euler pitch of R = Rz(yaw) Ry(pitch) Rx(roll) and
//   angle_x the Euler roll up to a cos(pitch) factor on its sine (exact for a
//   pure roll). Unlike Euler roll, which flips to +-pi as a robot falls flat
//   on its face, both stay in [-pi/2, pi/2] and say how the robot lies:
//   face down angle_y ~ +pi/2, on its back ~ -pi/2, on its right side
//   angle_x ~ +pi/2, on its left ~ -pi/2. Both independent of yaw.
//
// writeV5InertialSlots() turns such a sample into the V5's libagent slots,
// with the V5's signs and units (common/libagent/Inertial.hpp: GyroscopeZ and
// AccelerometerX/Z negated, GyrX/GyrY and AccX/Y/Z in raw counts).
#pragma once

#include <Eigen/Geometry>

namespace simswift::sensors {

// The IMU's accelerometer point in the torso frame (Aldebaran's NAO V5 (H25) documentation), m.
inline Eigen::Vector3d accelerometerPoint() { return {-0.008, 0.00606, 0.027}; }

// (angle_x, angle_y) of a torso orientation (torso-to-world rotation), rad.
Eigen::Vector2d torsoRollPitch(const Eigen::Matrix3d& torso_to_world);

// Specific force (m/s^2, torso axes) for the IMU point's world acceleration
// `a_world` (m/s^2) with gravity of magnitude `gravity` along -z.
Eigen::Vector3d specificForce(const Eigen::Matrix3d& torso_to_world, const Eigen::Vector3d& a_world,
                              double gravity);

// One inertial sample in physical terms (see above).
struct ImuSample {
  Eigen::Vector3d gyro = Eigen::Vector3d::Zero();            // rad/s, torso axes, right-handed
  Eigen::Vector3d specific_force = Eigen::Vector3d::Zero();  // m/s^2, torso axes
  double angle_x = 0;                                        // rad (roll)
  double angle_y = 0;                                        // rad (pitch)
};

// Writes the 14 inertial slots (InertialSensor_AccX .. AccelerometerZ) of a
// libagent sensor array as a NAO V5 reports `sample`. The legacy raw values
// (GyrX/GyrY, AccX/Y/Z) take the calibrated values' sign times
// `gyr_raw_sign` / `acc_raw_sign` (+1 or -1; SensorConfig).
void writeV5InertialSlots(const ImuSample& sample, int gyr_raw_sign, int acc_raw_sign, float* sensors);

// Finite-differences between ticks: a = (v_now - v_prev) / dt for the
// accelerometer point's world velocity, and the torso orientation change for
// the gyro.
class ImuModel {
 public:
  // Starts (or restarts, e.g. after a teleport) from the current state, so
  // the first reading has a = 0 and the instantaneous angular velocity
  // rather than a spike.
  void reset(const Eigen::Matrix3d& torso_to_world, const Eigen::Vector3d& point_velocity_world) {
    prev_rotation_ = torso_to_world;
    prev_velocity_ = point_velocity_world;
    primed_ = false;
    has_history_ = true;
  }
  // `omega_world` (rad/s, world) is used only for the first tick after a reset.
  ImuSample update(const Eigen::Matrix3d& torso_to_world, const Eigen::Vector3d& omega_world,
                   const Eigen::Vector3d& point_velocity_world, double dt, double gravity);

 private:
  Eigen::Matrix3d prev_rotation_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d prev_velocity_ = Eigen::Vector3d::Zero();
  bool has_history_ = false;  // prev_* hold a state
  bool primed_ = false;       // prev_* are one tick old (not a fresh reset)
};

}  // namespace simswift::sensors
