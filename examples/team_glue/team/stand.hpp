// The team's Motion stand-in: holds the pose it finds at stiffness 1 and
// turns the head to a commanded yaw. Team code only: no simswift header.
#pragma once

#include "team/types.hpp"

class TeamStand {
 public:
  explicit TeamStand(double head_yaw_deg) : head_yaw_deg_(head_yaw_deg) {}
  void tick(const SensorValues& sensors, JointValues& command);

 private:
  double head_yaw_deg_;
  bool have_pose_ = false;
  JointValues hold_{};
};
