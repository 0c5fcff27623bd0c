#include "team/stand.hpp"

bool offNao = true;

void TeamStand::tick(const SensorValues& sensors, JointValues& command) {
  if (!have_pose_) {
    hold_ = sensors.joints;
    for (float& s : hold_.stiffnesses) s = 1.0f;
    have_pose_ = true;
  }
  command = hold_;
  // The head turns by at most 1 deg per 10 ms tick toward the target.
  const double now = RAD2DEG(sensors.joints.angles[Joints::HeadYaw]);
  const double step = MAX(-1.0, MIN(1.0, head_yaw_deg_ - now));
  command.angles[Joints::HeadYaw] = static_cast<float>(DEG2RAD(now + step));
}
