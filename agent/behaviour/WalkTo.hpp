// WalkTo skill: walk to a field point (optionally ending at a heading),
// steering round teammates and goal posts with a repulsive potential field;
// an oncoming teammate is passed on the left (SkillConfig::keep_right).
// A hard keep-out round teammates removes any command that would close on
// one (SkillConfig::keep_out_distance); what the chest sonars report close
// by is kept clear of the same way (SkillConfig::sonar_*).
// Far from the target the robot faces its direction of travel (the walk is
// fastest forward); near it, it side-steps and turns to the final heading.
// Every command is inside the walk's limits: (forward/F)^2 + (left/L)^2 <= 1
// and |turn| <= T, with F, L, T the walk's max speeds.
#pragma once

#include <optional>
#include <vector>

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
  // The way v (field frame, mm/s, toward the target) bent round oncoming
  // teammates: right to pass one on the left, left for one clearly to the
  // right (SkillConfig::keep_right, pass_*). v unchanged without one.
  Point2 passOncoming(const BehaviourInputs& in, Point2 target, Point2 v) const;
  // Repulsion from teammates and posts at the robot's position, field frame, mm/s.
  Point2 repulsion(const BehaviourInputs& in, Point2 target) const;
  // Field-frame velocity v (mm/s) without its parts closing on a teammate
  // nearer than keep_out_distance (centre to centre).
  Point2 keepOut(const BehaviourInputs& in, Point2 v) const;
  // A teammate (or an echo of the sonars, placed one robot radius beyond
  // it) nearer the target than this robot stands within reach
  // (keep_out_distance + 100 mm) and the target within
  // blocked_arrive_distance: tick() reports arrival (no final heading asked)
  // unless the sonars hear something near (it steps back first).
  bool blocked(const BehaviourInputs& in, Point2 target) const;
  // Field positions (mm) of what the sonars report close by
  // (SkillConfig::sonar_*): one per side that counts as near; none without
  // sonar_avoid. Kept clear of as teammates are.
  std::vector<Point2> sonarObstacles(const BehaviourInputs& in) const;
  // A side of the sonars counts as near (and sonar_avoid): tick() steps back.
  bool sonarNear(const BehaviourInputs& in) const;
  // Scale (forward, left) into the walk's ellipse; clamp turn.
  static blackboard::BodyCommand clampToWalk(blackboard::BodyCommand b, const WalkLimits& w);

 private:
  SkillConfig s_;
  FieldGeometry f_;
};

}  // namespace agent::behaviour
