// The NAO's chest sonars: two emitter/receiver pairs, 40 kHz, 60 deg cones.
//
// Placement (Aldebaran NAO documentation, "Sonars", positions in the torso
// frame): the four transducers sit at (53.7, +-34.1, 69.8) mm yawed +-20 deg
// and (47.7, +-41.6, 50.9) mm yawed +-25 deg. We model each side as one beam
// from the midpoint of its pair, (50.7, +-37.85, 60.35) mm, yawed
// +-SensorConfig::sonar_yaw (25 deg) and tilted by sonar_pitch (0 = level in
// torso axes), the "Left" beam looking to the robot's left.
//
// A cone is sampled by a fixed fan of rays (a grid of 7.5 deg steps in yaw
// and 12 deg in pitch, corners outside the cone dropped: 33 rays), cast
// every sonar_period_ticks (the NAO's 100 ms sonar cycle). The carpet is
// deliberately silent: the lower rays of a level chest sonar would reach it
// inside 0.8 m, which the real transducers' directivity and the carpet's
// absorption largely suppress; a ray whose hit lies on the plane z = 0
// gives no echo.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <functional>
#include <vector>

namespace simswift::sensors {

struct SonarBeam {
  Eigen::Vector3d origin;  // m, torso frame
  double yaw = 0;          // rad, + = to the robot's left
  double pitch = 0;        // rad, + = down
};
SonarBeam leftSonarBeam(double yaw, double pitch);
SonarBeam rightSonarBeam(double yaw, double pitch);

// Unit ray directions (torso frame) sampling the beam's cone of full
// opening angle `cone` (rad).
std::vector<Eigen::Vector3d> sonarFan(const SonarBeam& beam, double cone);

// Echoes (m) from ray hit distances: hits below `min_range` read min_range,
// hits beyond `max_range` are dropped, hits closer than `separation` to the
// previous echo merge into it; sorted nearest first, up to 10, the rest
// kNoEcho.
std::array<float, 10> sonarEchoes(std::vector<double> hits, double min_range, double max_range,
                                  double separation, float no_echo);

// Casts the fan of `beam` with the torso at `torso` (world). `ray` returns
// the hit distance (m) along a unit world direction, or < 0 for none.
// Hits on the ground plane (z = 0) are discarded. Returns hit distances.
using RayFunction =
    std::function<double(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double max_range)>;
std::vector<double> castSonar(const SonarBeam& beam, double cone, const Eigen::Isometry3d& torso,
                              double max_range, const RayFunction& ray);

}  // namespace simswift::sensors
