// The vision oracle: what each robot's cameras would detect this frame,
// from the true state of the World, through the detector model
// (VisionConfig). The thesis's SimVisionAdapter (section 3.2.3) turned the
// old simulator's perfect, 120-degree vision into field features; this goes
// along its future-work list (section 6.1): real fields of view, distance
// limits, detection probability falling with distance, noise per object
// kind, false positives, occlusion by robots and posts, balls on lines
// harder to see, blindness while falling or lying.
//
// Reads: World (link poses of every robot, ball position, field), the
// VisionConfig, the scenario seed. Writes: observations (CameraFrame).
// Nothing here changes the World, so the state hash does not depend on it.
//
// Per camera, in this fixed order (observeCamera, one stage per kind of object):
//  1. Camera pose = head link pose (HeadPitch child) x mounting (rUNSWift 2017 release, robot/libagent
//     section 1), plus the per-robot camera position error (table 3.1).
//  2. Candidates, each tested for: inside the image rectangle (the robot's
//     lens: VisionConfig::hfov_deg x vfov_deg), distance from the feet within [min, max], no robot (other than
//     the observer and the object itself) or goal post within
//     occlusion_margin_mm of the line of sight from the camera, and a Bernoulli draw with the detection probability.
//     Ball; goal posts (base); robots (torso, reported at the feet); marks;
//     centre circle (enough of it visible); corners; lines (points every
//     line_step_mm, consecutive visible points form a piece).
//  3. Gaussian noise on distance and bearing (and orientation), then false
//     positives.
// Randomness: a counter-based stream per (scenario seed, robot, camera,
// frame, object), so one object's draws never depend on what else was seen.
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/libagent/CameraShared.hpp"
#include "sim/vision/FieldFeatures.hpp"
#include "sim/vision/VisionConfig.hpp"
#include "sim/world/World.hpp"

namespace simswift::vision {

// A robot's ground frame: origin midway between the feet on the ground,
// x along the torso's heading. Field frame, m / rad.
struct GroundFrame {
  GroundFrame() = default;
  GroundFrame(const Eigen::Vector2d& o, double h) : origin(o), heading(h), cos_h(std::cos(h)), sin_h(std::sin(h)) {}
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  double heading = 0;
  double cos_h = 1, sin_h = 0;  // of heading (cached: toRobot runs thousands of times a frame)
  // Field point (m) -> robot-relative (m).
  Eigen::Vector2d toRobot(const Eigen::Vector2d& p) const;
};

// One observation plus what only the simulator knows (for tests and logs,
// never handed to the robot code).
struct SeenObject {
  common::libagent::Observation obs;
  bool false_positive = false;
  int source = -1;  // index of the true object: robot index, post, mark, corner, line; -1 for the ball or a phantom
};

// Fixed camera mounting on the head (Aldebaran's NAO V5 (H25) documentation): the same figures as
// sim/camera/CameraModel.cpp, which the vision library cannot link (it needs
// OSMesa); tests/vision checks that the two agree.
struct CameraMount {
  Eigen::Vector3d offset;  // m, in the HeadPitch child link frame
  double pitch_down;       // rad
};
CameraMount cameraMount(int camera);  // 0 top, 1 bottom

class VisionOracle {
 public:
  VisionOracle(const FieldConfig& field, VisionConfig config, uint64_t seed);
  ~VisionOracle();
  VisionOracle(const VisionOracle&) = delete;
  VisionOracle& operator=(const VisionOracle&) = delete;

  // SPL team number and jersey colour (0 blue, 1 red) of each World robot
  // (index = robot index); unlisted robots: team 0, blue.
  void setTeams(std::vector<int> team_of_robot, std::vector<int> colour_of_robot = {});

  // Both cameras of `robot` at camera frame `frame` (top camera first).
  std::vector<SeenObject> observe(const World& world, int robot, int64_t frame);
  // Writes `robot`'s observations into frame.observations / num_observations,
  // highest priority first (ball, posts, robots, marks, circle, corners,
  // lines), at most kMaxObservations. Returns how many did not fit.
  int fill(const World& world, int robot, common::libagent::CameraFrame& frame);

  // What fill() last told `robot` of the true ball (false positives never
  // count): the camera frame index it was in (-1: never) and the detected
  // distance (mm, from the point between the feet; the nearer of the two
  // cameras' detections). The experiment's found rule reads it, so "sees the
  // ball" is exactly what the robot's perception was given.
  struct BallSighting {
    int64_t frame = -1;       // last camera frame that saw the true ball (-1: never)
    double distance_mm = 0;   // as measured in that frame (nearest camera)
    int consecutive = 0;      // frames in a row, ending with `frame`, that saw it
  };
  BallSighting ballSighting(int robot) const {
    return robot >= 0 && robot < static_cast<int>(sightings_.size()) ? sightings_[robot] : BallSighting{};
  }

  // True camera pose (camera frame in the field, m; x along the optical axis,
  // y left, z up), without the camera position error.
  Eigen::Isometry3d cameraPose(const World& world, int robot, int camera) const;
  GroundFrame groundFrame(const World& world, int robot) const;
  // Lying (torso tilted beyond lying_tilt_deg) or falling.
  bool blind(const World& world, int robot) const;
  // Would a point (field, m) be inside camera `camera`'s image?
  bool inImage(const Eigen::Isometry3d& camera_pose, const Eigen::Vector3d& point) const {
    return inView(camera_pose.inverse(), point);
  }

  const VisionConfig& config() const { return config_; }
  const FieldFeatures& features() const { return features_; }
  int64_t dropped() const { return dropped_; }  // observations that did not fit a frame, summed

 private:
  class CameraView;  // one camera at one frame and its stages (VisionOracle.cpp)
  void observeCamera(const World& world, int robot, int camera, int64_t frame, std::vector<SeenObject>& out);
  void refreshBounds(const World& world);
  // inImage with the field-to-camera transform already inverted.
  bool inView(const Eigen::Isometry3d& field_to_camera, const Eigen::Vector3d& point) const;
  // True if something (a robot other than those ignored, or a post other
  // than ignore_post) lies on the segment from `from` to `to` (field, m),
  // stopping `stop_short` before `to`.
  bool occluded(const World& world, const Eigen::Vector3d& from, const Eigen::Vector3d& to, double stop_short,
                int ignore_robot_a, int ignore_robot_b, int ignore_post);

  FieldFeatures features_;
  VisionConfig config_;
  uint64_t seed_;
  double tan_half_h_, tan_half_v_;
  double ball_radius_, line_half_width_;
  std::vector<int> teams_, colours_;
  dGeomID sight_ = nullptr;  // capsule along a line of sight (not in any space)
  double margin_ = 0.02;     // m, its radius
  // Per-robot axis-aligned bounds of the collision geoms (field, m), cached per world tick.
  int64_t bounds_tick_ = -1;
  std::vector<Eigen::AlignedBox3d> bounds_;
  int64_t dropped_ = 0;
  std::vector<BallSighting> sightings_;  // by robot index (fill)
  void observeThesisBall(const World& world, int robot, std::vector<SeenObject>& out) const;
};

}  // namespace simswift::vision
