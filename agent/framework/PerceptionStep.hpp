// A step run with each camera frame before the Perception modules.
#pragma once

#include <cstdint>

#include "common/libagent/CameraImages.hpp"
#include "common/libagent/CameraShared.hpp"

namespace agent::framework {

// An extra Perception step for tests and tools (e.g. reading the rendered
// images): run first in the Perception thread with each camera frame.
class PerceptionStep {
 public:
  virtual ~PerceptionStep() = default;
  virtual void step(const common::libagent::CameraFrame& frame) { ++frames_; }
  int64_t frames() const { return frames_; }
  // The rendered images (null unless the simulator renders); hold the frame
  // passed to step() when frame.images_valid is 1. Set by RobotProgram.
  void setImages(const common::libagent::CameraImages* images) { images_ = images; }
  const common::libagent::CameraImages* images() const { return images_; }

 protected:
  int64_t frames_ = 0;
  const common::libagent::CameraImages* images_ = nullptr;
};

}  // namespace agent::framework
