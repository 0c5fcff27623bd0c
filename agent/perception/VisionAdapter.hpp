// The vision adapter: turns a camera frame's detections (the simulator's
// detector model, or on a robot the vision pipeline's output) into
// robot-relative measurements from the feet, split for their consumers:
// the ball (closest detection), field features for localisation, robots.
//
// Input observations are robot-relative already (origin between the feet on
// the ground, x forward, y left, mm): the adapter checks and completes them
// (distance / heading from x, y or the reverse), drops what cannot be used
// (non-finite, beyond max_distance) and nothing is reported while the robot
// is falling, lying or getting up (the camera then sees sky and carpet).
// A seen piece of field line (two ends) becomes line points along it, one
// every line_point_spacing mm; corners keep their L / T / X shape.
// Units: mm, rad.
#pragma once

#include "agent/blackboard/Blackboard.hpp"

namespace agent::perception {

struct VisionAdapterConfig {
  double max_distance = 9000.0;  // mm: farther detections are dropped
  double line_point_spacing = 400.0;  // mm between the points a seen line piece becomes
};

// `fallen`: Motion's posture says falling, lying or getting up.
blackboard::VisionMeasurements adaptVision(const blackboard::FrameInfo& frame, bool fallen,
                                           const VisionAdapterConfig& cfg = {});

}  // namespace agent::perception
