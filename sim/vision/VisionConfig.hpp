// The detector model's settings: what the simulated vision of a robot can
// see and how well. One DetectorSpec per kind of object, all with defaults,
// read from a scenario's `vision:` block (see readVisionConfig):
//
//   vision:
//     preset: simswift2017     # the ball as the thesis's simulated vision saw
//                              #   it (BallModel::Thesis2017); other objects as below
//     enabled: on              # off: frames carry no observations
//     noise: on                # off (or the scenario's noise: off): exact
//                              #   observations, no misses, no false positives
//     camera_offset_mm: 5      # camera position error, uniform +-, once per robot
//     lying_tilt_deg: 45       # torso tilt beyond which the robot sees nothing
//     falling_rate_dps: 120    # ... nor while the torso turns this fast and tilts > 15 deg
//     occlusion_margin_mm: 20  # a robot or post this close to a line of sight hides the object
//     line_step_mm: 100        # spacing of the points tested along lines
//     min_line_mm: 200         # shorter visible pieces of line are not reported
//     circle_min_fraction: 0.3 # of the centre circle visible to report it
//     ball:          {max_distance_mm: 2500, on_line_factor: 0.6, ...}
//     goal_posts:    {...}
//     robots:        {...}
//     corners:       {...}     # line intersections L, T, X
//     lines:         {...}
//     centre_circle: {...}
//     penalty_marks: {...}
//
// Units are in the key names (mm, deg, dps = deg/s); rates and
// probabilities are per camera per frame (30 Hz). Bad values throw
// ConfigError naming the file, line and key.
#pragma once

#include <array>
#include <optional>
#include <string>

namespace common::config {
class YamlReader;
}
namespace simswift {
using common::config::YamlReader;
}

namespace simswift::vision {

// Kinds of object the oracle reports (order = output priority).
enum class Feature : int { Ball = 0, GoalPost, Robot, PenaltyMark, CentreCircle, Corner, Line };
constexpr int kNumFeatures = 7;
const char* featureKey(Feature f);  // its key in the `vision:` block, e.g. "goal_posts"

// How one kind of object is detected. Distances are robot-relative ground
// distances from the point between the feet (mm).
struct DetectorSpec {
  bool enabled = true;
  double min_distance_mm = 0;
  double max_distance_mm = 2500;   // beyond: never seen (the thesis's reliable ball range)
  // Detection probability: p_near up to falloff_start_mm, then falling
  // linearly to p_at_max at max_distance_mm. Assumed shape (no published
  // rUNSWift figures): tune against real logs.
  double p_near = 1.0;
  double falloff_start_mm = 1500;
  double p_at_max = 0.7;
  // Gaussian noise, robot-relative. The distance sigma combines (root sum of
  // squares) an absolute part, a part proportional to the distance and the
  // camera's vertical-angle error carried to the ground:
  //   sigma_d^2 = abs^2 + (fraction * d)^2 + ((h^2 + dc^2) / h * sigma_elev)^2
  // (h camera height above the object, dc horizontal camera-object distance).
  // Defaults: thesis table 3.1, the old simulator (SimSpark) noise, read as
  // SimSpark documents it: distance sigma 0.0965 % of the distance,
  // horizontal angle 0.1225 deg, vertical angle 0.1480 deg.
  double distance_sigma_mm = 0;
  double distance_sigma_fraction = 0.000965;
  double bearing_sigma_deg = 0.1225;
  double elevation_sigma_deg = 0.1480;
  double orientation_sigma_deg = 0;  // robots, corners, centre circle: error of the reported orientation
  // Phantom detections: probability per camera per frame of one false
  // positive of this kind at a random ground point the camera sees within
  // [min, max] distance. The old simulator had none (thesis section 3.3.1.1).
  double false_positive_rate = 0;
  // Ball only: detection probability times this when the ball lies on a
  // painted line (white on white). 1 = no effect.
  double on_line_factor = 1.0;

  // Detection probability at robot-relative distance d (mm), 0 outside [min, max].
  double probability(double d_mm) const;
};

// How the ball is seen. Detector: the detector model above (range,
// image, occlusion, misses, phantoms, noise). Thesis2017: the thesis's
// simulated vision (rUNSWift 2018 release, SimVisionAdapter): the ball up to
// 2500 mm and within +-30 deg of the camera's heading, no vertical test,
// no misses, phantoms, occlusion or noise; `vision: {preset: simswift2017}`.
enum class BallModel { Detector, Thesis2017 };

struct VisionConfig {
  bool enabled = true;
  BallModel ball_model = BallModel::Detector;
  double thesis_ball_half_angle_deg = 30;  // Thesis2017: either side of the camera's heading
  bool noise = true;                 // false: exact, no misses, no false positives
  // Each camera's field of view, deg; unset: the robot's own lens (the V5's
  // 60.9 x 47.6, the V6's 56.3 x 43.7: common/nao/NaoFacts.hpp), which the
  // runner fills in from the robots' body interface. An override changes
  // what the oracle shows, not the lens the robot program plans its head
  // scans for (its body's: agent/program/BodyConnection): a what-if for the
  // detector, not a different camera.
  std::optional<double> hfov_deg, vfov_deg;
  double camera_offset_mm = 5;       // table 3.1: camera position error, uniform +-, once per robot
  double lying_tilt_deg = 45;        // torso z axis from vertical: lying, sees nothing
  double falling_rate_dps = 120;     // torso angular speed that means falling ...
  double falling_tilt_deg = 15;      // ... once tilted this far
  // An object is hidden when a robot or a post comes this close to the line
  // of sight to it (its centre, or its ground point), i.e. hides about
  // 2 x this much of its width. Also closes the gaps of the slim collision
  // model (between the legs, under the arms).
  double occlusion_margin_mm = 20;
  double line_step_mm = 100;
  double min_line_mm = 200;
  double circle_min_fraction = 0.3;
  std::array<DetectorSpec, kNumFeatures> detectors = defaultDetectors();

  DetectorSpec& operator[](Feature f) { return detectors[static_cast<int>(f)]; }
  const DetectorSpec& operator[](Feature f) const { return detectors[static_cast<int>(f)]; }

  // Per-kind defaults: the thesis's ball range (2500 mm) and assumed ranges
  // for the rest (rUNSWift 2017 order of magnitude); noise as table 3.1.
  static std::array<DetectorSpec, kNumFeatures> defaultDetectors();
};

// Reads a `vision:` map (keys as in the header comment) over `base`.
// Unknown keys and out-of-range values throw ConfigError naming file, line and key.
VisionConfig readVisionConfig(const YamlReader& r, VisionConfig base = {});

}  // namespace simswift::vision
