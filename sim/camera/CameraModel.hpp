// The NAO V5 camera model: where the two cameras sit on the head and how a
// world point maps to a pixel (ideal pinhole, no distortion, no rolling
// shutter). The renderer draws with exactly this model, so tests can compare
// a rendered image against project().
//
// Frames: a camera frame has x along the optical axis (forward), y left,
// z up -- the robot convention, so at zero head angles and zero pitch it is
// parallel to the torso. World frame as in World.hpp. Units: m, rad, px.
// Pixel coordinates are continuous: u to the right, v down, pixel (col, row)
// covering [col, col+1) x [row, row+1), so its centre is (col+0.5, row+0.5).
#pragma once

#include <Eigen/Geometry>
#include <optional>

#include "common/nao/NaoFacts.hpp"

namespace simswift::camera {

enum CameraId : int { kTop = 0, kBottom = 1 };

struct Intrinsics {
  int width = 640, height = 480;  // px
  double fx = 0, fy = 0;          // focal lengths, px
  double cx = 0, cy = 0;          // principal point, px (continuous coordinates)

  // The NAO camera at the given resolution through `lens` (the V5's 60.9 x
  // 47.6 deg, the V6's 56.3 x 43.7 deg: common/nao/NaoFacts.hpp), principal
  // point at the image centre. fx = (w/2)/tan(hfov/2): ~544.2 px at 640 wide
  // on a V5, ~598.1 px on a V6; fy from the vertical FOV.
  static Intrinsics nao(int width = 640, int height = 480,
                        const common::nao::CameraLens& lens = common::nao::kV5CameraLens);
  // A free camera with the given horizontal FOV (rad) and square pixels.
  static Intrinsics fromHorizontalFov(int width, int height, double hfov);
};

// Fixed camera mounting on the head, Aldebaran's NAO V5 (H25) documentation: offsets (m) from
// the frame of the link the HeadPitch joint moves, and the downward pitch.
struct NaoCameraMount {
  Eigen::Vector3d offset;  // m, in the head frame
  double pitch_down;       // rad, positive = looking down
};
NaoCameraMount naoCameraMount(CameraId id);
// Camera frame in the head frame.
Eigen::Isometry3d cameraInHead(CameraId id);

// A camera placed in the world.
struct CameraModel {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // camera frame in world
  Intrinsics intrinsics = Intrinsics::nao();

  static CameraModel naoCamera(const Eigen::Isometry3d& head_pose, CameraId id,
                               int width = 640, int height = 480,
                               const common::nao::CameraLens& lens = common::nao::kV5CameraLens);

  // Pixel (continuous) of a world point; nullopt if it is not in front of
  // the camera (x <= 1 mm in the camera frame). May fall outside the image.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& world_point) const;
  // Unit ray direction (world frame) through a pixel (continuous coordinates).
  Eigen::Vector3d rayDirection(double u, double v) const;
  bool inImage(const Eigen::Vector2d& px) const {
    return px.x() >= 0 && px.y() >= 0 && px.x() < intrinsics.width && px.y() < intrinsics.height;
  }
};

// Camera pose at `eye` looking at `target` (m, world), image "up" toward +z.
Eigen::Isometry3d lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target);

}  // namespace simswift::camera
