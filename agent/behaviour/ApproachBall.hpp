// ApproachBall skill: walk to approach_distance behind the ball on the line
// from the kick target through the ball, facing the target, watching the
// ball. Lined up when within approach_tolerance and kick_angle_tolerance.
#pragma once

#include "agent/behaviour/WalkTo.hpp"

namespace agent::behaviour {

class ApproachBall {
 public:
  ApproachBall(const SkillConfig& s, const FieldGeometry& f) : s_(s), walk_(s, f) {}
  struct Output {
    blackboard::BodyCommand body;
    blackboard::HeadCommand head;
    bool lined_up = false;
  };
  // ball: field mm (the best estimate available).
  Output tick(const BehaviourInputs& in, Point2 ball) const;
  Pose2 standOff(Point2 ball) const;  // where the robot should stand (field)

 private:
  SkillConfig s_;
  WalkTo walk_;
};

}  // namespace agent::behaviour
