// The pinhole model and the NAO camera mounting (Aldebaran's NAO V5 (H25) documentation).
#include <gtest/gtest.h>

#include <cmath>

#include "sim/camera/CameraModel.hpp"

using namespace simswift::camera;

TEST(CameraModel, NaoIntrinsicsMatchThePublishedFieldOfView) {
  const Intrinsics k = Intrinsics::nao(640, 480);
  EXPECT_NEAR(k.fx, 544.0, 1.0);  // about 544 px at 640x480 (60.9 deg horizontal field of view, Aldebaran's NAO V5 (H25) documentation)
  EXPECT_NEAR(k.fy, 544.0, 1.0);
  EXPECT_DOUBLE_EQ(k.cx, 320.0);
  EXPECT_DOUBLE_EQ(k.cy, 240.0);
  // The image edges are the FOV's edges: 60.9 deg across, 47.6 deg down.
  EXPECT_NEAR(2 * std::atan(320.0 / k.fx) * 180 / M_PI, 60.9, 1e-9);
  EXPECT_NEAR(2 * std::atan(240.0 / k.fy) * 180 / M_PI, 47.6, 1e-9);
  const Intrinsics big = Intrinsics::nao(1280, 960);
  EXPECT_NEAR(big.fx, 2 * k.fx, 1e-9);
}

// The V6's OV5640 lens, 56.3 x 43.7 deg (Aldebaran's NAOqi 2.8 NAO V6 camera
// specifications): about 598 px at 640x480, 10 % longer than the V5's.
TEST(CameraModel, V6IntrinsicsMatchItsPublishedFieldOfView) {
  const Intrinsics k = Intrinsics::nao(640, 480, common::nao::kV6CameraLens);
  EXPECT_NEAR(k.fx, 598.05, 0.05);  // 320 / tan(28.15 deg), worked by hand
  EXPECT_NEAR(k.fy, 598.53, 0.05);  // 240 / tan(21.85 deg)
  EXPECT_DOUBLE_EQ(k.cx, 320.0);
  EXPECT_DOUBLE_EQ(k.cy, 240.0);
  EXPECT_NEAR(k.fx / Intrinsics::nao(640, 480).fx, 1.0987, 0.0005);
}

TEST(CameraModel, MountingOffsetsAndPitch) {
  const Eigen::Isometry3d top = cameraInHead(kTop), bottom = cameraInHead(kBottom);
  EXPECT_NEAR((top.translation() - Eigen::Vector3d(0.05871, 0, 0.06364)).norm(), 0, 1e-12);
  EXPECT_NEAR((bottom.translation() - Eigen::Vector3d(0.05071, 0, 0.01774)).norm(), 0, 1e-12);
  // Optical axis (camera x) tipped down by 1.2 and 39.7 deg.
  const Eigen::Vector3d at = top.linear().col(0), ab = bottom.linear().col(0);
  EXPECT_NEAR(std::asin(-at.z()) * 180 / M_PI, 1.2, 1e-9);
  EXPECT_NEAR(std::asin(-ab.z()) * 180 / M_PI, 39.7, 1e-9);
  EXPECT_NEAR(at.y(), 0, 1e-12);
}

TEST(CameraModel, ProjectionConventions) {
  CameraModel c;
  c.pose = lookAt({0, 0, 1}, {5, 0, 1});  // looking along +x, level
  const auto centre = c.project({3, 0, 1});
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->x(), 320, 1e-9);
  EXPECT_NEAR(centre->y(), 240, 1e-9);
  const auto left_up = c.project({2, 0.5, 1.2});  // left of and above the axis
  ASSERT_TRUE(left_up);
  EXPECT_NEAR(left_up->x(), 320 - c.intrinsics.fx * 0.25, 1e-9);
  EXPECT_NEAR(left_up->y(), 240 - c.intrinsics.fy * 0.1, 1e-9);
  EXPECT_FALSE(c.project({-1, 0, 1}));  // behind
  // rayDirection inverts project.
  const Eigen::Vector3d d = c.rayDirection(left_up->x(), left_up->y());
  EXPECT_NEAR((d - Eigen::Vector3d(2, 0.5, 0.2).normalized()).norm(), 0, 1e-12);
}
