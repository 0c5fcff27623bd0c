// The team's test (team code only): its stand holds the robot up, the FSRs
// (read by the team's own names) carry the robot's mass, and the head
// reaches the commanded 20 deg. Exit 0 on success.
#include <cstdio>

#include "simswift_glue.hpp"
#include "team/stand.hpp"

int main() {
  TeamStand stand(20.0);  // deg of head yaw
  const glue::Outcome o = glue::run("duration: 3\nseed: 5\nrobots:\n  - {team: 19, player: 1, x: 0.5, y: -1.0}\n",
                                    2.0, [&](const SensorValues& s, JointValues& j) { stand.tick(s, j); });
  double fsr = 0;  // kg
  for (int f : {Sensors::LFoot_FSR_FrontLeft, Sensors::LFoot_FSR_FrontRight, Sensors::LFoot_FSR_RearLeft,
                Sensors::LFoot_FSR_RearRight, Sensors::RFoot_FSR_FrontLeft, Sensors::RFoot_FSR_FrontRight,
                Sensors::RFoot_FSR_RearLeft, Sensors::RFoot_FSR_RearRight})
    fsr += o.last.sensors[f];
  const double head = RAD2DEG(o.last.joints.angles[Joints::HeadYaw]);
  std::printf("fallen %d, at (%.3f, %.3f) m, FSR sum %.2f kg, head yaw %.1f deg\n", o.fallen, o.x, o.y, fsr, head);
  // 5.305 kg: the NAO V5's mass (Aldebaran's datasheet); 20 % for one
  // tick's sway. Head within 2 deg of the command.
  const bool ok = !o.fallen && fsr > 0.8 * 5.305 && fsr < 1.2 * 5.305 && head > 18.0 && head < 22.0;
  return ok ? 0 : 1;
}
