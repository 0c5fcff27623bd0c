// The camera matrix: where each camera is and where it looks, in the robot
// frame, from the sensor values at frame time -- the leg and head joint
// angles (kinematics with the NAO hardware facts, common/nao/NaoFacts.hpp)
// and the torso's tilt from the inertial unit.
//
// Robot frame: origin on the ground midway between the two soles, z up
// (against gravity), x forward along the torso's heading, y left; mm.
// Camera frame: x along the optical axis, y left, z up in the image (the
// NAO convention used by the simulator's camera model).
#pragma once

#include "common/libagent/AgentShared.hpp"
#include "agent/motion/Kinematics.hpp"
#include "common/nao/NaoFacts.hpp"

namespace agent::perception {

struct CameraPose {
  motion::Mat3 rotation;  // camera axes in the robot frame
  motion::Vec3 position;  // mm, camera centre in the robot frame
};

// The camera's pose from one set of sensor values.
CameraPose cameraPose(const common::libagent::SensorValues& sensors, common::nao::Camera camera);

// Robot-frame ground point (z = 0) to the camera's view: bearing left of the
// optical axis and elevation above it (rad). False if it is behind the camera.
bool viewAngles(const CameraPose& cam, double x, double y, double* horizontal, double* vertical);

// Whether a ground point (mm, robot frame) lies inside the camera's field of
// view through `lens` (the V5's by default; common/nao/NaoFacts.hpp).
bool inFieldOfView(const CameraPose& cam, double x, double y,
                   const common::nao::CameraLens& lens = common::nao::kV5CameraLens);

}  // namespace agent::perception
