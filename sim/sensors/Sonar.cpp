#include "sim/sensors/Sonar.hpp"

#include <algorithm>
#include <cmath>

namespace simswift::sensors {

namespace {
// Midpoint of the two transducers of the left side (mm -> m), see header.
const Eigen::Vector3d kLeftOrigin{0.0507, 0.03785, 0.06035};
}  // namespace

SonarBeam leftSonarBeam(double yaw, double pitch) { return {kLeftOrigin, yaw, pitch}; }

SonarBeam rightSonarBeam(double yaw, double pitch) {
  return {Eigen::Vector3d(kLeftOrigin.x(), -kLeftOrigin.y(), kLeftOrigin.z()), -yaw, pitch};
}

std::vector<Eigen::Vector3d> sonarFan(const SonarBeam& beam, double cone) {
  // Offsets on a grid of cone/8 (7.5 deg) in yaw, where thin objects such as
  // posts and legs must not slip between rays, and cone/5 (12 deg) in pitch,
  // keeping those within the half-angle: 33 rays for a 60 deg cone.
  const double half = 0.5 * cone;
  const double yaw_step = cone / 8.0, pitch_step = cone / 5.0;
  const Eigen::Matrix3d axis = (Eigen::AngleAxisd(beam.yaw, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(beam.pitch, Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix();
  std::vector<Eigen::Vector3d> dirs;
  for (int j = -2; j <= 2; ++j) {
    for (int i = -4; i <= 4; ++i) {
      const double dy = i * yaw_step, dp = j * pitch_step;
      if (std::hypot(dy, dp) > half + 1e-9) continue;
      // Offset direction in beam axes: yaw about z, then pitch (+ = down)
      // about y; rotation about +y by +dp tips +x toward -z.
      const Eigen::Vector3d d = Eigen::AngleAxisd(dy, Eigen::Vector3d::UnitZ()) *
                                (Eigen::AngleAxisd(dp, Eigen::Vector3d::UnitY()) * Eigen::Vector3d::UnitX());
      dirs.push_back((axis * d).normalized());
    }
  }
  return dirs;
}

std::array<float, 10> sonarEchoes(std::vector<double> hits, double min_range, double max_range,
                                  double separation, float no_echo) {
  std::array<float, 10> out;
  out.fill(no_echo);
  std::vector<double> kept;
  for (double h : hits)
    if (h >= 0 && h <= max_range) kept.push_back(std::max(h, min_range));
  std::sort(kept.begin(), kept.end());
  int n = 0;
  double last = -1e9;
  for (double h : kept) {
    if (n >= 10) break;
    if (h - last < separation) continue;  // same object as the previous echo
    out[n++] = static_cast<float>(h);
    last = h;
  }
  return out;
}

std::vector<double> castSonar(const SonarBeam& beam, double cone, const Eigen::Isometry3d& torso,
                              double max_range, const RayFunction& ray) {
  std::vector<double> hits;
  const Eigen::Vector3d origin = torso * beam.origin;
  if (origin.z() <= 0) return hits;  // chest on or under the carpet: no usable echo
  for (const Eigen::Vector3d& d_torso : sonarFan(beam, cone)) {
    const Eigen::Vector3d d = torso.linear() * d_torso;
    const double h = ray(origin, d, max_range);
    if (h < 0) continue;
    // Distance along this ray to the carpet plane; a hit there (or beyond,
    // which cannot happen with an opaque carpet) is the ground: no echo.
    if (d.z() < 0) {
      const double t_ground = -origin.z() / d.z();
      if (h >= t_ground - 0.005) continue;
    }
    hits.push_back(h);
  }
  return hits;
}

}  // namespace simswift::sensors
