// Foot bumpers and the touch buttons.
//
// Each NAO foot has two bumpers at the toe, a left and a right half. One is
// pressed when something other than the carpet (another robot, a post, the
// ball) pushes on the foot ahead of SensorConfig::bumper_min_x (m, ankle
// frame); the halves split at the sole's mid-line, y = +-5.62 mm (the sole
// spans 38.78 mm inside and 50.02 mm outside the ankle; Aldebaran's NAO V5 (H25) documentation).
// The chest button and the three head pads have no physical model: the
// scenario presses them through SensorSuite::setButton.
#pragma once

#include <Eigen/Core>

namespace simswift::sensors {

// Mid-line of the sole (m, ankle frame): left foot +, right foot -.
constexpr double kSoleMidY = 0.5 * (0.05002 - 0.03878);

struct BumperHit {
  bool left = false;
  bool right = false;
};

// Which bumper a non-ground contact at `point` (m, ankle frame) presses.
// `left_foot` selects the mid-line's side.
BumperHit bumperFor(const Eigen::Vector3d& point, bool left_foot, double min_x);

enum class Button { Chest, HeadFront, HeadMiddle, HeadRear };

}  // namespace simswift::sensors
