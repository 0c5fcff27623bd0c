// Which side of the chest sonars has an object close by, over behaviour
// frames (the era's rule: rUNSWift 2016 release, util/Sonar.py; numbers in
// SkillConfig). Per side a count between -sonar_min_frames and
// sonar_hold_frames, starting at 0: a frame whose first echo is under
// sonar_near_distance raises it by one, or straight to the top once it has
// climbed to 0; any other frame lowers it by one. The side counts while the
// count is above 0: after min_frames + 1 near frames in a row from rest, and
// for hold_frames frames after the last.
#pragma once

#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/behaviour/BehaviourInputs.hpp"

namespace agent::behaviour {

class SonarFilter {
 public:
  explicit SonarFilter(const SkillConfig& c) : c_(c) {}
  // left / right: this frame's first echo of each side, mm. Returns the
  // state with the near flags set.
  SonarState update(double left, double right);

 private:
  void step(int side, double echo);
  SkillConfig c_;
  int count_[2] = {0, 0};
};

}  // namespace agent::behaviour
