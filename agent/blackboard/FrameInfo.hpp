// What the Perception thread receives at each camera frame (30 Hz of
// simulated time): the frame's time, the body's sensor values at that time
// (joint angles for the camera matrix) and the frame's detector
// observations. Written by the robot program before the Perception modules
// run; read by the vision adapter, localisation, ball tracker and behaviour.
// Odometry and posture at frame time are in the Motion section (the Motion
// thread is between ticks while a frame is processed).
// Units: s, us, mm, rad. Observations are robot-relative (origin between the
// feet on the ground, x forward, y left).
#pragma once

#include <cstdint>

#include "common/libagent/AgentShared.hpp"
#include "common/libagent/CameraShared.hpp"

namespace agent::blackboard {

struct FrameInfo {
  int64_t sim_time_us = 0;  // us, when the frame was taken
  int64_t frame_index = -1; // 0, 1, 2, ... (-1: no frame yet)
  double time = 0;          // s, the same time as a double
  double dt = 0;            // s since the previous frame (0 on the first)
  // Sensors at frame time (the Motion tick that ended just before the frame).
  common::libagent::SensorValues sensors{};
  int32_t num_observations = 0;
  common::libagent::Observation observations[common::libagent::kMaxObservations]{};
  bool images_valid = false;  // the CameraImages block holds this frame
};

// The latest sensors the Motion thread read (written every 10 ms tick by the
// robot program before the Motion modules run).
struct SensorFrame {
  common::libagent::SensorValues values{};
  int64_t sim_time_us = 0;
  double time = 0;  // s
};

}  // namespace agent::blackboard
