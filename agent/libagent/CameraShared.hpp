// The camera side of the robot interface: what the Perception thread waits on.
//
// On a NAO, Perception blocks on the camera driver until a frame arrives
// (30 Hz). In simswift the simulator plays the driver: it fills a CameraBlock
// (part of the extension object beside the libagent block, SimExtension.hpp)
// at 30 Hz of simulated time, posts `frame_ready`, and waits on
// `perception_done` (with a watchdog) before stepping on.
//
// A frame carries the vision oracle's observations (what a detector would
// report: robot-relative, mm / rad) and, when rendering is on, the images.
// Image buffers live in a separate block (see CameraImages) so robots that do
// not render pay nothing.
#pragma once

#include <semaphore.h>

#include <atomic>
#include <cstdint>

namespace agent::libagent {

enum class ObservationType : int32_t { Ball = 0, GoalPost, Robot, LineCorner, FieldLine, CentreCircle, PenaltyCross };

// One detection, relative to the robot (origin between the feet on the
// ground, x forward, y left). Distance mm, heading rad (left positive).
struct Observation {
  ObservationType type;
  int32_t camera;   // 0 = top, 1 = bottom
  float distance;   // mm
  float heading;    // rad
  float x, y;       // mm, robot-relative
  int32_t team;     // robots: team number seen (or -1)
};

constexpr int kMaxObservations = 64;

struct CameraFrame {
  int64_t sim_time_us;  // simulated time the frame was taken
  int64_t frame_index;  // 0, 1, 2, ... at 30 Hz
  int32_t num_observations;
  Observation observations[kMaxObservations];
  int32_t images_valid; // 1 if the CameraImages block holds this frame's images
};

struct CameraBlock {
  uint32_t magic;
  CameraFrame frame;               // written before frame_ready is posted
  sem_t frame_ready;               // posted by the simulator at 30 Hz
  sem_t perception_done;           // posted by Perception when it has finished
  std::atomic<int32_t> shutdown;   // set when the run ends
  // 1 if a Perception thread waits on frame_ready. Set (by announce())
  // before the program answers its first tick; the simulator posts frames
  // (and waits for perception_done) only to robots that have one.
  std::atomic<int32_t> consumer;
};

}  // namespace agent::libagent
