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
    : scene_(world.field(), std::move(config.scene)), lens_(config.lens) {
  for (int c = 0; c < common::libagent::kNumCameras; ++c)
    setResolution(static_cast<CameraId>(c), config.resolution[c]);
  for (int i = 0; i < world.numRobots(); ++i) scene_.preloadModel(world.robot(i).model());
}

void RobotCameras::setTeams(std::vector<int> team_of_robot) { teams_ = std::move(team_of_robot); }

int RobotCameras::checkedId(CameraId id) {
  if (id != kTop && id != kBottom) throw std::invalid_argument("RobotCameras: no camera " + std::to_string(id));
  return id;
}

void RobotCameras::setResolution(CameraId id, common::libagent::ImageSize size) {
  checkedId(id);
  if (size.width <= 0 || size.height <= 0 || size.width % 2 != 0 || size.width > common::libagent::kMaxImageWidth ||
      size.height > common::libagent::kMaxImageHeight)
    throw std::invalid_argument("RobotCameras: resolution " + std::to_string(size.width) + "x" +
                                std::to_string(size.height) + " is not an even width up to 1280x960");
  resolution_[id] = size;
}

void RobotCameras::setResolution(common::libagent::ImageSize size) {
  setResolution(kTop, size);
  setResolution(kBottom, size);
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
  const common::libagent::ImageSize size = resolution_[checkedId(id)];
  return CameraModel::naoCamera(body.linkPose(headLink(body.model())), id, size.width, size.height, lens_);
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
  out.frame_index = frame_index >= 0 ? frame_index : static_cast<int64_t>(std::floor(t * kCameraHz + 1e-9));
  out.sim_time_us = sim_time_us >= 0 ? sim_time_us : static_cast<int64_t>(std::llround(t * 1e6));
  for (int c = 0; c < common::libagent::kNumCameras; ++c) {
    out.valid[c] = 0;
    out.size[c] = resolution_[c];
    renderer_.render(scene_, view(world, robot, static_cast<CameraId>(c)), out.rgb[c]);
    rgbToYuyv(out.rgb[c], resolution_[c].width, resolution_[c].height, out.yuv422[c]);
    out.valid[c] = 1;
  }
}

void RobotCameras::renderCamera(const World& world, int robot, CameraId id, common::libagent::ImageSize size,
                                uint8_t* yuyv, uint8_t* rgb) {
  if (robot < 0 || robot >= world.numRobots())
    throw std::out_of_range("RobotCameras::renderCamera: no robot " + std::to_string(robot));
  const common::libagent::ImageSize kept = resolution_[checkedId(id)];
  setResolution(id, size);  // checked; view() draws at the camera's resolution
  syncScene(world);
  renderer_.render(scene_, view(world, robot, id), rgb);
  rgbToYuyv(rgb, size.width, size.height, yuyv);
  resolution_[id] = kept;
}

}  // namespace simswift::camera
