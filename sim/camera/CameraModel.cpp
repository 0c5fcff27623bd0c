#include "sim/camera/CameraModel.hpp"

#include <cmath>
#include <stdexcept>

#include "common/nao/NaoFacts.hpp"

namespace simswift::camera {

Intrinsics Intrinsics::nao(int width, int height, const common::nao::CameraLens& lens) {
  Intrinsics k;
  k.width = width;
  k.height = height;
  k.fx = (width / 2.0) / std::tan(lens.horizontal_fov / 2);
  k.fy = (height / 2.0) / std::tan(lens.vertical_fov / 2);
  k.cx = width / 2.0;
  k.cy = height / 2.0;
  return k;
}

Intrinsics Intrinsics::fromHorizontalFov(int width, int height, double hfov) {
  Intrinsics k;
  k.width = width;
  k.height = height;
  k.fx = k.fy = (width / 2.0) / std::tan(hfov / 2);
  k.cx = width / 2.0;
  k.cy = height / 2.0;
  return k;
}

NaoCameraMount naoCameraMount(CameraId id) {
  // The NAO's hardware facts (common/nao/NaoFacts.hpp: mm in the
  // HeadPitch frame, rad down), in m.
  if (id == kTop || id == kBottom) {
    const common::nao::CameraMount& m = common::nao::cameraMount(id == kTop ? common::nao::Camera::Top
                                                                         : common::nao::Camera::Bottom);
    return {Eigen::Vector3d(m.x, m.y, m.z) * 1e-3, m.pitch_down};
  }
  throw std::invalid_argument("naoCameraMount: camera id must be 0 (top) or 1 (bottom)");
}

Eigen::Isometry3d cameraInHead(CameraId id) {
  NaoCameraMount m = naoCameraMount(id);
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = m.offset;
  // A positive rotation about +y tips the forward (x) axis down toward -z.
  t.linear() = Eigen::AngleAxisd(m.pitch_down, Eigen::Vector3d::UnitY()).toRotationMatrix();
  return t;
}

CameraModel CameraModel::naoCamera(const Eigen::Isometry3d& head_pose, CameraId id, int width,
                                   int height, const common::nao::CameraLens& lens) {
  CameraModel c;
  c.pose = head_pose * cameraInHead(id);
  c.intrinsics = Intrinsics::nao(width, height, lens);
  return c;
}

std::optional<Eigen::Vector2d> CameraModel::project(const Eigen::Vector3d& world_point) const {
  Eigen::Vector3d p = pose.inverse() * world_point;  // camera frame, m
  if (p.x() <= 1e-3) return std::nullopt;
  const Intrinsics& k = intrinsics;
  // y left -> u decreases; z up -> v decreases.
  return Eigen::Vector2d(k.cx - k.fx * p.y() / p.x(), k.cy - k.fy * p.z() / p.x());
}

Eigen::Vector3d CameraModel::rayDirection(double u, double v) const {
  const Intrinsics& k = intrinsics;
  Eigen::Vector3d d(1.0, -(u - k.cx) / k.fx, -(v - k.cy) / k.fy);
  return (pose.linear() * d).normalized();
}

Eigen::Isometry3d lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  Eigen::Vector3d x = (target - eye).normalized();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  if (std::abs(x.dot(up)) > 0.999) up = Eigen::Vector3d::UnitX();  // looking straight down/up
  Eigen::Vector3d y = up.cross(x).normalized();  // left
  Eigen::Vector3d z = x.cross(y);
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear().col(0) = x;
  t.linear().col(1) = y;
  t.linear().col(2) = z;
  t.translation() = eye;
  return t;
}

}  // namespace simswift::camera
