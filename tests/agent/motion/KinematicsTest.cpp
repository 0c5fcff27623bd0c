// Leg inverse kinematics checked by forward kinematics over a grid of
// reachable foot poses (mm, rad).
#include <gtest/gtest.h>

#include <cmath>

#include "agent/motion/Kinematics.hpp"

using namespace agent::motion;

namespace {

double posError(const FootPose& a, const FootPose& b) {
  const Vec3 d = a.position - b.position;
  return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}
double rotError(const FootPose& a, const FootPose& b) {
  double e = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) e = std::max(e, std::fabs(a.rotation.m[i][j] - b.rotation.m[i][j]));
  return e;
}

}  // namespace

TEST(Kinematics, ZeroAnglesIsStraightLeg) {
  const FootPose f = legForward(Leg::Left, LegAngles{});
  EXPECT_NEAR(f.position.x, 0, 1e-9);
  EXPECT_NEAR(f.position.y, 0, 1e-9);
  EXPECT_NEAR(f.position.z, -(NaoDims::kThighLength + NaoDims::kTibiaLength + NaoDims::kFootHeight), 1e-9);
}

TEST(Kinematics, KneeBendMovesFootBackAndUp) {
  LegAngles q;
  q.knee = 0.5;
  const FootPose f = legForward(Leg::Right, q);
  EXPECT_LT(f.position.x, -10);  // tibia swings backward (mm)
  EXPECT_GT(f.position.z, -248.09);
}

// FK(IK(target)) == target within 0.1 mm over a grid of reachable poses,
// each leg on its own (all six joints free).
TEST(Kinematics, InverseThenForwardReproducesTargetSingleLeg) {
  int checked = 0;
  for (Leg leg : {Leg::Left, Leg::Right}) {
    for (double x = -60; x <= 60; x += 20)
      for (double y = -40; y <= 40; y += 20)
        for (double z = -230; z <= -170; z += 15)
          for (double yaw = -0.4; yaw <= 0.41; yaw += 0.2)
            for (double roll = -0.1; roll <= 0.11; roll += 0.1) {
              const FootPose target = footPose(x, y, z, yaw, roll, 0.05);
              bool ok = false;
              const LegAngles q = legInverse(leg, target, &ok);
              ASSERT_TRUE(ok);
              const FootPose back = legForward(leg, q);
              ASSERT_LT(posError(back, target), 0.1)
                  << "leg " << int(leg) << " x " << x << " y " << y << " z " << z << " yaw " << yaw;
              ASSERT_LT(rotError(back, target), 1e-6);
              ++checked;
            }
  }
  EXPECT_GT(checked, 1000);
}

// Both legs with one shared HipYawPitch: exact when the feet mirror in yaw,
// which is how the walk turns.
TEST(Kinematics, BothLegsSharedYawPitchMirroredYaw) {
  for (double yaw = -0.3; yaw <= 0.31; yaw += 0.05)
    for (double xl = -50; xl <= 50; xl += 25)
      for (double xr = -50; xr <= 50; xr += 25) {
        const FootPose l = footPose(xl, 10, -200, yaw);
        const FootPose r = footPose(xr, -15, -190, -yaw);
        const auto q = legsInverse(l, r);
        EXPECT_DOUBLE_EQ(q[0].hip_yaw_pitch, q[1].hip_yaw_pitch);
        EXPECT_LT(posError(legForward(Leg::Left, q[0]), l), 0.1);
        EXPECT_LT(posError(legForward(Leg::Right, q[1]), r), 0.1);
      }
}

TEST(Kinematics, HipYawPitchTurnsFootOutwardForPositiveLeftYaw) {
  // A left foot yawed to the left (outward) needs negative LHipYawPitch on
  // the NAO (the joint opens the legs when negative).
  const LegAngles q = legInverse(Leg::Left, footPose(0, 0, -200, 0.3));
  EXPECT_LT(q.hip_yaw_pitch, -0.1);
  const LegAngles r = legInverse(Leg::Right, footPose(0, 0, -200, -0.3));
  EXPECT_LT(r.hip_yaw_pitch, -0.1);
}

TEST(Kinematics, UnreachableTargetIsClampedNotNaN) {
  bool ok = true;
  const LegAngles q = legInverse(Leg::Left, footPose(0, 0, -400, 0), &ok);
  EXPECT_FALSE(ok);
  EXPECT_FALSE(std::isnan(q.knee));
  EXPECT_NEAR(q.knee, 0, 1e-6);
}
