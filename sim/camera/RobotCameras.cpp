#include "sim/camera/RobotCameras.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/camera/Yuv.hpp"

namespace simswift::camera {

namespace {
constexpr double kCameraHz = 30.0;  // NAO camera frame rate (simulated time)
}  // namespace

RobotCameras::RobotCameras(const World& world, RobotCamerasConfig config)
    : scene_(world.field(), std::move(config.scene)), width_(config.width), height_(config.height), lens_(config.lens) {
  setResolution(config.width, config.height);
  for (int i = 0; i < world.numRobots(); ++i) scene_.preloadModel(world.robot(i).model());
}

void RobotCameras::setTeams(std::vector<int> team_of_robot) { teams_ = std::move(team_of_robot); }

void RobotCameras::setResolution(int width, int height) {
  if (width <= 0 || height <= 0 || width % 2 != 0 || width > common::libagent::kMaxImageWidth ||
      height > common::libagent::kMaxImageHeight)
    throw std::invalid_argument("RobotCameras: resolution " + std::to_string(width) + "x" +
                                std::to_string(height) + " is not an even width up to 1280x960");
  width_ = width;
  height_ = height;
}

int RobotCameras::headLink(const RobotModel& model) {
  const int j = model.jointIndex("HeadPitch");
  if (j < 0) throw std::runtime_error("camera: the robot model has no HeadPitch joint to carry the cameras");
  return model.joints()[j].child_link;
}

void RobotCameras::syncScene(const World& world) {
  const int n = world.numRobots();
  scene_.robots.resize(n);
  for (int i = 0; i < n; ++i) {
    const RobotBody& body = world.robot(i);
    RobotDrawState& s = scene_.robots[i];
    s.model = &body.model();
    s.team = i < static_cast<int>(teams_.size()) ? teams_[i] : 0;
    const int links = static_cast<int>(body.model().links().size());
    s.link_poses.resize(links);
    for (int l = 0; l < links; ++l) s.link_poses[l] = body.linkPose(l);
  }
  scene_.show_ball = world.hasBall();
  scene_.ball_position = world.ballPosition();
  scene_.ball_orientation = world.ballOrientation();
}

CameraModel RobotCameras::camera(const World& world, int robot, CameraId id) const {
  const RobotBody& body = world.robot(robot);
  return CameraModel::naoCamera(body.linkPose(headLink(body.model())), id, width_, height_, lens_);
}

CameraView RobotCameras::view(const World& world, int robot, CameraId id) const {
  CameraView v;
  v.camera = camera(world, robot, id);
  v.draw.hide_robot = robot;
  v.draw.hide_link = headLink(world.robot(robot).model());
  return v;
}

void RobotCameras::fillImages(const World& world, int robot, common::libagent::CameraImages& out,
                              int64_t frame_index, int64_t sim_time_us) {
  if (robot < 0 || robot >= world.numRobots())
    throw std::out_of_range("RobotCameras::fillImages: no robot " + std::to_string(robot));
  syncScene(world);
  const double t = world.time();  // s
  out.magic = common::libagent::kCameraImagesMagic;
  out.width = width_;
  out.height = height_;
  out.frame_index = frame_index >= 0 ? frame_index : static_cast<int64_t>(std::floor(t * kCameraHz + 1e-9));
  out.sim_time_us = sim_time_us >= 0 ? sim_time_us : static_cast<int64_t>(std::llround(t * 1e6));
  for (int c = 0; c < common::libagent::kNumCameras; ++c) {
    out.valid[c] = 0;
    renderer_.render(scene_, view(world, robot, static_cast<CameraId>(c)), out.rgb[c]);
    rgbToYuyv(out.rgb[c], width_, height_, out.yuv422[c]);
    out.valid[c] = 1;
  }
}

}  // namespace simswift::camera
