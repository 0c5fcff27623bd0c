// The NAO cameras of robots in a World: keeps a Scene in step with the World
// and renders a robot's top and bottom camera into a CameraImages block (RGB
// and YUV422) for the robot code.
//
// Runner hook (rendering is off unless asked): create one RobotCameras after
// the World has its robots, call setTeams() with each robot's team, then at
// every 30 Hz camera frame call fillImages(world, robot, images, frame,
// time_us) for each robot whose images are wanted, and set
// CameraFrame::images_valid = 1. The camera poses follow the head link at
// the moment of the call (no rolling shutter).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "common/libagent/CameraImages.hpp"
#include "sim/camera/CameraModel.hpp"
#include "sim/camera/Renderer.hpp"
#include "sim/camera/Scene.hpp"
#include "sim/world/World.hpp"

namespace simswift::camera {

struct RobotCamerasConfig {
  // Per camera (index CameraId): 640x480 (default) or 1280x960.
  common::libagent::ImageSize resolution[common::libagent::kNumCameras];
  common::nao::CameraLens lens = common::nao::kV5CameraLens;  // the robots' (one kind per world)
  SceneOptions scene;
};

class RobotCameras {
 public:
  explicit RobotCameras(const World& world, RobotCamerasConfig config = {});

  // Team of each world robot (index = World robot index); unlisted = team 0.
  void setTeams(std::vector<int> team_of_robot);
  // Camera `id`'s image size: 640x480 or 1280x960 (anything up to 1280x960
  // with an even width works).
  void setResolution(CameraId id, common::libagent::ImageSize size);
  // Both cameras at one size.
  void setResolution(common::libagent::ImageSize size);
  common::libagent::ImageSize resolution(CameraId id) const { return resolution_[checkedId(id)]; }

  // Copies robot link poses and the ball into the scene.
  void syncScene(const World& world);

  // Camera `id` of robot `robot` as things stand (head link pose now).
  CameraModel camera(const World& world, int robot, CameraId id) const;
  // The view to render: that camera, with the robot's own head hidden.
  CameraView view(const World& world, int robot, CameraId id) const;

  // Syncs the scene, renders both cameras of `robot` and fills `out`
  // (RGB and YUYV, valid flags, each camera's size, frame index, time). frame_index < 0
  // means "the 30 Hz frame at the world's time"; sim_time_us < 0 means the
  // world's time.
  void fillImages(const World& world, int robot, common::libagent::CameraImages& out,
                  int64_t frame_index = -1, int64_t sim_time_us = -1);

  // Renders camera `id` of `robot` alone at `size` (an even width up to
  // 1280x960) into `yuyv` (width x height x 2 bytes), through `rgb`
  // (width x height x 3 bytes of scratch): a V4L2 device's frame
  // (sim/bridge/V4l2Devices.hpp), at the size its program set.
  void renderCamera(const World& world, int robot, CameraId id, common::libagent::ImageSize size, uint8_t* yuyv,
                    uint8_t* rgb);

  Scene& scene() { return scene_; }
  Renderer& renderer() { return renderer_; }

  // Index of the link the HeadPitch joint moves (the cameras' parent).
  static int headLink(const RobotModel& model);

 private:
  // `id` if it names a camera, else invalid_argument (never an index past the array).
  static int checkedId(CameraId id);

  Scene scene_;
  Renderer renderer_;
  std::vector<int> teams_;
  common::libagent::ImageSize resolution_[common::libagent::kNumCameras];
  common::nao::CameraLens lens_;
};

}  // namespace simswift::camera
