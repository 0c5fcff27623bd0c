// The simulator's one fall detector (run statistics, tests): a robot is down
// once its torso frame origin drops below kFallHeight and up again above
// kStandHeight (hysteresis, so lying still or getting up counts one fall).
// The robot code has its own, from its sensors (agent/motion MotionModule);
// this one is ground truth from the physics.
#pragma once

namespace simswift::runner {

struct FallDetector {
  static constexpr double kFallHeight = 0.20;   // m: torso origin below this = fallen
  static constexpr double kStandHeight = 0.25;  // m: back above this = up again

  bool fallen = false;
  int falls = 0;

  // Torso frame origin height (m, field frame); returns true on a new fall.
  bool update(double torso_z) {
    if (!fallen && torso_z < kFallHeight) {
      fallen = true;
      ++falls;
      return true;
    }
    if (fallen && torso_z > kStandHeight) fallen = false;
    return false;
  }
};

}  // namespace simswift::runner
