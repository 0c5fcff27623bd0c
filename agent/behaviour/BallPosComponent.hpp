// BallPosComponent: raises the probability of the segment where the ball is
// sighted now: P_ball += ball_pos_rate * dt, then normalise.
#pragma once

#include "agent/behaviour/DistributionComponent.hpp"

namespace agent::behaviour {

class BallPosComponent : public DistributionComponent {
 public:
  explicit BallPosComponent(double rate_per_s) : rate_(rate_per_s) {}
  const char* name() const override { return "BallPosComponent"; }
  void apply(PositionalDistribution& d, const BehaviourInputs& in, double dt) override {
    if (in.ball.seen_now && dt > 0) d.add(d.segmentAt(in.ball.field), rate_ * dt);
  }

 private:
  double rate_;  // probability mass per second of sighting
};

}  // namespace agent::behaviour
