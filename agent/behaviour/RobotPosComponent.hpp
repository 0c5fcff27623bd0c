// RobotPosComponent: a robot that stands in a segment and does not see the
// ball makes that segment less likely:
// P_robot *= exp(-robot_pos_rate * dt) while the ball is not seen, normalised.
// Not while penalised (off the field) or fallen (not looking).
#pragma once

#include <cmath>

#include "agent/behaviour/DistributionComponent.hpp"

namespace agent::behaviour {

class RobotPosComponent : public DistributionComponent {
 public:
  explicit RobotPosComponent(double rate_per_s) : rate_(rate_per_s) {}
  const char* name() const override { return "RobotPosComponent"; }
  void apply(PositionalDistribution& d, const BehaviourInputs& in, double dt) override {
    if (in.game.penalised || in.self.fallen) return;
    if (!in.ball.seen_now && dt > 0)
      d.scale(d.segmentAt(position(in.self.pose)), std::exp(-rate_ * dt));
  }

 private:
  double rate_;  // 1/s
};

}  // namespace agent::behaviour
