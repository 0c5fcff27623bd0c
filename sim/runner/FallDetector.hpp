// The simulator's one fall detector (run statistics, tests): a robot is down
// once its torso frame origin drops below kFallHeight and up again above
// kStandHeight (hysteresis, so lying still or getting up counts one fall).
// The robot code has its own, from its sensors (agent/motion ActionMotion);
// this one is ground truth from the physics.
//
// Attribution: a fall counts as a robot-contact fall too (contact_falls) if
// one of the robot's links touched another robot's link during the
// kContactWindow s before the fall was detected, or in the tick it was (the
// caller says so through robot_contact_recent). The window covers a push's
// topple: a standing NAO knocked over reaches kFallHeight about 0.5-1 s
// after the blow (measured in tests/runner: test_runner.cpp).
#pragma once

namespace simswift::runner {

struct FallDetector {
  static constexpr double kFallHeight = 0.20;   // m: torso origin below this = fallen
  static constexpr double kStandHeight = 0.25;  // m: back above this = up again
  static constexpr double kContactWindow = 2.0;  // s before a fall in which a robot contact counts

  bool fallen = false;
  int falls = 0;
  int contact_falls = 0;  // of falls, those within kContactWindow of touching another robot

  // Torso frame origin height (m, field frame); returns true on a new fall.
  bool update(double torso_z, bool robot_contact_recent = false) {
    if (!fallen && torso_z < kFallHeight) {
      fallen = true;
      ++falls;
      if (robot_contact_recent) ++contact_falls;
      return true;
    }
    if (fallen && torso_z > kStandHeight) fallen = false;
    return false;
  }
};

}  // namespace simswift::runner
