// IMU physics: specific force (what an ideal accelerometer measures),
// roll/pitch signs, finite differencing. The V5's slot signs and units are
// InertialSlotsTest's.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/sensors/Imu.hpp"

using namespace simswift::sensors;
using Eigen::AngleAxisd;
using Eigen::Matrix3d;
using Eigen::Vector3d;

TEST(ImuMath, UprightAtRestFeelsPlusG) {
  const Vector3d a = specificForce(Matrix3d::Identity(), Vector3d::Zero(), 9.81);
  EXPECT_NEAR(a.x(), 0, 1e-12);
  EXPECT_NEAR(a.y(), 0, 1e-12);
  EXPECT_NEAR(a.z(), 9.81, 1e-12);
}

TEST(ImuMath, FreeFallReadsZero) {
  const Vector3d a = specificForce(Matrix3d::Identity(), Vector3d(0, 0, -9.81), 9.81);
  EXPECT_NEAR(a.norm(), 0, 1e-12);
}

TEST(ImuMath, LeaningForwardGivesPositivePitch) {
  const Matrix3d r = AngleAxisd(0.3, Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Vector2d rp = torsoRollPitch(r);
  EXPECT_NEAR(rp.y(), 0.3, 1e-12);
  EXPECT_NEAR(rp.x(), 0.0, 1e-12);
  // The torso's z axis tips toward world +x: the top leans forward.
  EXPECT_GT((r * Vector3d::UnitZ()).x(), 0);
  // Gravity's reaction leans back in torso axes: -x and +z.
  const Vector3d a = specificForce(r, Vector3d::Zero(), 9.81);
  EXPECT_NEAR(a.x(), -9.81 * std::sin(0.3), 1e-9);
  EXPECT_NEAR(a.z(), 9.81 * std::cos(0.3), 1e-9);
}

TEST(ImuMath, LeaningRightGivesPositiveRoll) {
  const Matrix3d r = AngleAxisd(0.4, Vector3d::UnitX()).toRotationMatrix();
  EXPECT_LT((r * Vector3d::UnitZ()).y(), 0);  // the top leans to the right (-y)
  EXPECT_NEAR(torsoRollPitch(r).x(), 0.4, 1e-12);
}

TEST(ImuMath, RollPitchIgnoreYaw) {
  const Matrix3d tilt = (AngleAxisd(0.2, Vector3d::UnitY()) * AngleAxisd(-0.1, Vector3d::UnitX())).toRotationMatrix();
  for (double yaw : {0.0, 1.0, -2.5, 3.1}) {
    const Eigen::Vector2d rp = torsoRollPitch(AngleAxisd(yaw, Vector3d::UnitZ()).toRotationMatrix() * tilt);
    EXPECT_NEAR(rp.x(), std::asin(std::cos(0.2) * std::sin(-0.1)), 1e-12);  // ~Euler roll -0.1
    EXPECT_NEAR(rp.y(), 0.2, 1e-12);
  }
}

TEST(ImuMath, LyingFlatReadsWhichSideIsDown) {
  // Face down: torso x axis points at the carpet, z axis forward.
  Matrix3d face_down;
  face_down.col(0) = Vector3d(0.05, 0, -1).normalized();
  face_down.col(1) = Vector3d(0, 1, 0);
  face_down.col(2) = face_down.col(0).cross(face_down.col(1));
  Eigen::Vector2d rp = torsoRollPitch(face_down);
  EXPECT_NEAR(rp.y(), M_PI / 2, 0.06);
  EXPECT_NEAR(rp.x(), 0.0, 1e-9);  // Euler roll would read ~pi here
  // Slightly past vertical (head lower than hips): still face down, no flip.
  face_down.col(0) = Vector3d(-0.05, 0, -1).normalized();
  face_down.col(2) = face_down.col(0).cross(face_down.col(1));
  rp = torsoRollPitch(face_down);
  EXPECT_NEAR(rp.y(), M_PI / 2, 0.06);
  EXPECT_NEAR(rp.x(), 0.0, 1e-9);
  // On its right side: the left side (y axis) points up.
  rp = torsoRollPitch(AngleAxisd(M_PI / 2, Vector3d::UnitX()).toRotationMatrix());
  EXPECT_NEAR(rp.x(), M_PI / 2, 1e-6);
  EXPECT_NEAR(rp.y(), 0.0, 1e-9);
}

TEST(ImuMath, ModelDifferencesVelocityAndOrientation) {
  ImuModel m;
  const Matrix3d yaw90 = AngleAxisd(M_PI / 2, Vector3d::UnitZ()).toRotationMatrix();
  m.reset(yaw90, Vector3d::Zero());
  // First tick after a reset: the instantaneous angular velocity. World
  // rotation about +x seen from a torso facing +y is about torso -y.
  // Accelerating at 2 m/s^2 along world +x while facing world +y: the torso
  // feels it on its -y axis.
  const ImuSample t = m.update(yaw90, Vector3d(0.5, 0, 0), Vector3d(0.02, 0, 0), 0.01, 9.81);
  EXPECT_NEAR(t.specific_force.y(), -2.0, 1e-9);
  EXPECT_NEAR(t.specific_force.x(), 0.0, 1e-9);
  EXPECT_NEAR(t.specific_force.z(), 9.81, 1e-9);
  EXPECT_NEAR(t.gyro.y(), -0.5, 1e-12);
  EXPECT_NEAR(t.gyro.x(), 0.0, 1e-12);
  // Next tick: the torso turned 0.005 rad about world +x in 10 ms: the gyro
  // reads the tick's mean rate, 0.5 rad/s about torso -y, whatever the
  // instantaneous value passed in. Constant velocity: no acceleration.
  const Matrix3d turned = AngleAxisd(0.005, Vector3d::UnitX()).toRotationMatrix() * yaw90;
  const ImuSample t2 = m.update(turned, Vector3d(9, 9, 9), Vector3d(0.02, 0, 0), 0.01, 9.81);
  EXPECT_NEAR(t2.specific_force.y(), 0.0, 0.01);
  EXPECT_NEAR(t2.gyro.y(), -0.5, 1e-9);
  EXPECT_NEAR(t2.gyro.x(), 0.0, 1e-9);
  EXPECT_NEAR(t2.gyro.z(), 0.0, 1e-9);
}

TEST(ImuMath, FirstUpdateWithoutResetHasNoSpike) {
  ImuModel m;
  const ImuSample t = m.update(Matrix3d::Identity(), Vector3d::Zero(), Vector3d(3, 0, 0), 0.01, 9.81);
  EXPECT_NEAR(t.specific_force.x(), 0.0, 1e-12);
}
