#include "sim/camera/Overview.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "sim/camera/FrameDumper.hpp"
#include "sim/camera/Png.hpp"
#include "sim/camera/RobotCameras.hpp"
#include "sim/world/World.hpp"

namespace simswift::camera {


OverviewCamera::OverviewCamera(OverviewConfig cfg) : cfg_(std::move(cfg)) {
  if (!(cfg_.rate_hz > 0)) throw std::invalid_argument("overview: rate_hz must be > 0");
  if (cfg_.width <= 0 || cfg_.height <= 0 || cfg_.width % 2 || cfg_.height % 2)
    throw std::invalid_argument("overview: width and height must be positive and even");
  makeDirectories(cfg_.dir);
}

CameraModel OverviewCamera::cameraFor(const Scene& scene, const Eigen::Vector3d& followed) const {
  CameraModel c;
  c.intrinsics = Intrinsics::fromHorizontalFov(cfg_.width, cfg_.height, cfg_.hfov);
  if (cfg_.mode == OverviewConfig::Mode::Fixed) {
    Eigen::Vector3d eye = cfg_.eye;
    if (!std::isfinite(eye.x())) eye = Eigen::Vector3d(0, -(scene.field().carpetWidth() / 2 + 3.3), 5.0);
    c.pose = lookAt(eye, cfg_.target);
  } else {
    const Eigen::Vector3d target(followed.x(), followed.y(), 0);
    c.pose = lookAt(target + cfg_.follow_offset, target);
  }
  return c;
}

bool OverviewCamera::maybeCapture(Renderer& renderer, const Scene& scene, double t,
                                  const Eigen::Vector3d& followed) {
  // Due when t has reached frame k's time; the tolerance absorbs the tick
  // arithmetic (t = ticks * the body's tick).
  if (t + 1e-9 < frames_ / cfg_.rate_hz) return false;
  CameraView v;
  v.camera = cameraFor(scene, followed);
  v.far_clip = 100;
  rgb_.resize(size_t(cfg_.width) * cfg_.height * 3);
  renderer.render(scene, v, rgb_.data());
  char name[64];
  std::snprintf(name, sizeof name, "/overview_%06lld.png", static_cast<long long>(frames_));
  writePng(cfg_.dir + name, rgb_.data(), cfg_.width, cfg_.height);
  ++frames_;
  return true;
}

bool OverviewCamera::maybeCapture(RobotCameras& cameras, const World& world) {
  if (world.time() + 1e-9 < frames_ / cfg_.rate_hz) return false;  // skip the sync when nothing is due
  cameras.syncScene(world);
  Eigen::Vector3d followed = world.ballPosition();
  if (cfg_.mode == OverviewConfig::Mode::FollowRobot) {
    if (cfg_.robot < 0 || cfg_.robot >= world.numRobots())
      throw std::out_of_range("overview: no robot " + std::to_string(cfg_.robot) + " to follow");
    const RobotBody& b = world.robot(cfg_.robot);
    followed = b.linkPose(b.model().rootLink()).translation();
  }
  return maybeCapture(cameras.renderer(), cameras.scene(), world.time(), followed);
}

VideoResult OverviewCamera::finish(const std::string& mp4) const {
  if (frames_ == 0) return {false, "", "", "overview: no frames captured"};
  return VideoWriter::assemble(pattern(), cfg_.rate_hz, mp4);
}

}  // namespace simswift::camera
