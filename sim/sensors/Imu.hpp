// The NAO's torso inertial board: gyrometer, accelerometer and the board's
// fused torso angles. Pure maths here; SensorSuite feeds it the torso state.
//
// Conventions (NAO torso axes: x forward, y left, z up):
// - Gyroscope: torso angular velocity in torso axes, rad/s (right-hand rule),
//   averaged over the tick: the rotation vector of R_prev^T R_now divided by
//   the tick. Like the accelerometer's velocity difference, this is what a
//   sensor integrating over its 10 ms sample sees, and it leaves out the
//   solver's within-step velocity corrections that ODE's instantaneous body
//   velocity carries (on a standing robot those are ~0.05 rad/s RMS).
// - Accelerometer: the NAO reports gravity as negative z (an upright robot at
//   rest reads AccZ = -9.81). That is the sensor measuring the NEGATIVE of
//   proper acceleration: reading = R^T (a_world - g_world) * -1
//   = R^T (g_world - a_world), g_world = (0, 0, -9.81) m/s^2, a_world the
//   IMU point's acceleration. Leaning forward makes AccX positive; free fall
//   reads 0.
// - AngleX (roll) and AngleY (pitch), rad: the tilt of the torso as an
//   accelerometer-fused board sees it, i.e. the elevations of the torso's
//   axes above the horizontal plane:
//     AngleY = asin(-R(2,0))  (x axis pointing down = pitched forward),
//     AngleX = asin( R(2,1))  (y axis, the left side, pointing up = rolled right).
//   AngleY equals the Euler pitch of R = Rz(yaw) Ry(pitch) Rx(roll) and
//   AngleX the Euler roll up to a cos(pitch) factor on its sine (exact for a
//   pure roll). Unlike Euler roll, which flips to +-pi as a robot falls flat
//   on its face, both stay in [-pi/2, pi/2] and say how the robot lies:
//   face down AngleY ~ +pi/2, on its back ~ -pi/2, on its right side
//   AngleX ~ +pi/2, on its left ~ -pi/2. Positive AngleX (right-hand rule
//   about +x) = leaning to the robot's right; positive AngleY (about +y) =
//   leaning forward. Both independent of yaw.
#pragma once

#include <Eigen/Geometry>

namespace simswift::sensors {

// IMU sensor points in the torso frame (Aldebaran's NAO V5 (H25) documentation), m.
inline Eigen::Vector3d accelerometerPoint() { return {-0.008, 0.00606, 0.027}; }
inline Eigen::Vector3d gyroscopePoint() { return {-0.008, 0.006, 0.029}; }

// (AngleX, AngleY) of a torso orientation (torso-to-world rotation), rad.
Eigen::Vector2d torsoRollPitch(const Eigen::Matrix3d& torso_to_world);

// NAO accelerometer reading (m/s^2, torso axes) for the IMU point's world
// acceleration `a_world` (m/s^2) with gravity of magnitude `gravity` along -z.
Eigen::Vector3d naoAccelerometer(const Eigen::Matrix3d& torso_to_world,
                                 const Eigen::Vector3d& a_world, double gravity);

struct ImuTruth {
  Eigen::Vector3d gyro;   // rad/s, torso axes
  Eigen::Vector3d accel;  // m/s^2, torso axes, NAO sign
  double angle_x = 0;     // rad (roll)
  double angle_y = 0;     // rad (pitch)
};

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
  ImuTruth update(const Eigen::Matrix3d& torso_to_world, const Eigen::Vector3d& omega_world,
                  const Eigen::Vector3d& point_velocity_world, double dt, double gravity);

 private:
  Eigen::Matrix3d prev_rotation_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d prev_velocity_ = Eigen::Vector3d::Zero();
  bool has_history_ = false;  // prev_* hold a state
  bool primed_ = false;       // prev_* are one tick old (not a fresh reset)
};

}  // namespace simswift::sensors
