// HeadScan skill: the head sweeps 0 -> +scan_yaw -> -scan_yaw -> 0 at
// scan_speed (rad/s), so one sweep (4 scan_yaw / scan_speed s) sees
// +-(scan_yaw + camera_hfov / 2) around the body. Targets are absolute
// angles inside HeadYaw's range, speeds inside its limit.
// Also headLookAt: point the head at a robot-relative ground point.
#pragma once

#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/behaviour/Geometry.hpp"
#include "agent/blackboard/Blackboard.hpp"

namespace agent::behaviour {

class HeadScan {
 public:
  explicit HeadScan(const SkillConfig& s) : s_(s) {}
  void start(double time) { start_ = time; }
  blackboard::HeadCommand tick(double time) const;
  double sweepDuration() const;  // s, one full sweep
  bool sweepDone(double time) const { return time - start_ >= sweepDuration(); }
  double yawAt(double time) const;  // rad, the sweep's yaw at `time`
  double amplitude() const;         // rad, scan_yaw inside the head's limit
  double speed() const;             // rad/s, scan_speed inside the head's limit

 private:
  SkillConfig s_;
  double start_ = 0;
};

// Head command looking at a robot-relative ground point (mm): yaw toward it,
// pitch down more the nearer it is (SkillConfig's look_* fields).
blackboard::HeadCommand headLookAt(Point2 relative, const SkillConfig& s);

}  // namespace agent::behaviour
