// Localisation's estimate of the robot's pose on the field.
// Field frame: origin at the centre spot, x toward the opponent goal, y left;
// mm, rad (theta counter-clockwise from +x, in (-pi, pi]).
#pragma once

#include <cstdint>

namespace agent::blackboard {

struct FieldPose {
  double x = 0, y = 0;  // mm
  double theta = 0;     // rad
};

struct LocalisationEstimate {
  FieldPose pose;
  // Spread of the best hypothesis (1 sigma): mm, mm, rad.
  double sd_x = 0, sd_y = 0, sd_theta = 0;
  int32_t hypotheses = 0;      // separate modes the filter currently holds
  double confidence = 0;       // 0..1, recent mean observation likelihood
  // Flip / kidnap: the estimate jumped (more than odometry can explain).
  // `jumped` is true on the frame it happens; `jump_time` s of the last jump.
  bool jumped = false;
  int32_t jumps = 0;           // since start
  double jump_time = -1;       // s, -1 = never
  double time = 0;             // s, frame time of this estimate
};

}  // namespace agent::blackboard
