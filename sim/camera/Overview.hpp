// The whole-field overview camera and the video assembled from it.
//
// OverviewCamera renders a view of the field at a fixed rate of simulated
// time -- fixed high above the right-hand touch line, or following a robot
// or the ball -- and writes DIR/overview_<frame:06d>.png. VideoWriter then
// turns the PNG sequence into an MP4 with ffmpeg when ffmpeg is on PATH
// (libx264, or mpeg4 if libx264 is missing), else leaves the PNGs.
//
// Runner hook: after each World::step(), call maybeCapture(cameras, world);
// at the end of the run call finish(DIR/overview.mp4) and print its message.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/camera/CameraModel.hpp"
#include "sim/camera/Renderer.hpp"
#include "sim/camera/Scene.hpp"
#include "sim/video/VideoWriter.hpp"

namespace simswift {
class World;
}

namespace simswift::camera {

class RobotCameras;

// The video writer lives in sim/video (one home; the FindBall view uses it too).
using video::VideoResult;
using video::VideoWriter;

struct OverviewConfig {
  enum class Mode { Fixed, FollowRobot, FollowBall };
  Mode mode = Mode::Fixed;
  int robot = 0;                    // for FollowRobot (World index)
  double rate_hz = 10;              // frames per second of simulated time
  int width = 960, height = 540;    // px (even, for the video encoders)
  double hfov = 1.2;                // rad
  std::string dir = "overview";     // PNG folder (created)
  // Fixed mode: camera position and aim (m, field). Default (NaN): 3.3 m
  // beyond the carpet's right-hand edge, 5 m up, aimed at the centre.
  Eigen::Vector3d eye{NAN, NAN, NAN};
  Eigen::Vector3d target{0, -0.4, 0};
  // Follow modes: camera offset from the followed point (m, field axes).
  Eigen::Vector3d follow_offset{0, -2.8, 2.2};
};

class OverviewCamera {
 public:
  explicit OverviewCamera(OverviewConfig cfg);
  const OverviewConfig& config() const { return cfg_; }

  // Frame k is due at simulated time k / rate_hz (s). If one is due at time
  // t (s), renders it and writes the PNG; returns true if it wrote one.
  bool maybeCapture(Renderer& renderer, const Scene& scene, double t, const Eigen::Vector3d& followed);
  // Uses the RobotCameras' scene and renderer (syncing the scene first).
  bool maybeCapture(RobotCameras& cameras, const World& world);

  CameraModel cameraFor(const Scene& scene, const Eigen::Vector3d& followed) const;
  int64_t frames() const { return frames_; }
  std::string pattern() const { return cfg_.dir + "/overview_%06d.png"; }
  VideoResult finish(const std::string& mp4) const;

 private:
  OverviewConfig cfg_;
  int64_t frames_ = 0;
  std::vector<uint8_t> rgb_;
};

}  // namespace simswift::camera
