// WalkTo skill: walk to a field point (optionally ending at a heading),
// steering round teammates and goal posts with a repulsive potential field.
// Far from the target the robot faces its direction of travel (the walk is
// fastest forward); near it, it side-steps and turns to the final heading.
// Every command is inside the walk's limits: (forward/F)^2 + (left/L)^2 <= 1
// and |turn| <= T, with F, L, T the walk's max speeds.
#pragma once

#include <optional>

#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/behaviour/BehaviourInputs.hpp"
#include "agent/blackboard/Blackboard.hpp"

namespace agent::behaviour {

struct WalkToResult {
  blackboard::BodyCommand body;  // WALK (or STAND once arrived)
  bool arrived = false;
};

class WalkTo {
 public:
  WalkTo(const SkillConfig& s, const FieldGeometry& f) : s_(s), f_(f) {}
  // target: field mm; heading: final field heading (rad) or none;
  // arrive_distance: mm.
  WalkToResult tick(const BehaviourInputs& in, Point2 target, std::optional<double> heading,
                    double arrive_distance) const;
  // Repulsion from teammates and posts at the robot's position, field frame, mm/s.
  Point2 repulsion(const BehaviourInputs& in, Point2 target) const;
  // Scale (forward, left) into the walk's ellipse; clamp turn.
  static blackboard::BodyCommand clampToWalk(blackboard::BodyCommand b, const WalkLimits& w);

 private:
  SkillConfig s_;
  FieldGeometry f_;
};

}  // namespace agent::behaviour
