#include "sim/game/Sideline.hpp"

#include <algorithm>
#include <cmath>

namespace simswift::game {

PlanarPose sidelinePose(const FieldConfig& field, int team, double y, int slot) {
  const double own = team == 0 ? -1.0 : 1.0;  // sign of the own half's x
  const double side = y < 0 ? -1.0 : 1.0;
  PlanarPose p;
  // Level with the penalty mark, moved towards the centre line per slot.
  const double mark = field.length / 2 - kPenaltyMarkFromGoalLine;
  p.x = own * std::max(0.0, mark - slot * kSidelineSpacing);
  p.y = side * field.width / 2;
  p.theta = -side * M_PI / 2;  // face the field
  return p;
}

PlanarPose robotPose(const World& world, int robot) {
  const RobotBody::TorsoPose t = world.robot(robot).torsoPose();
  return {t.x, t.y, t.heading};
}

PlanarPose PenaltyPlacer::penalise(World& world, int robot, int team) {
  const PlanarPose from = robotPose(world, robot);
  // Next free slot at that spot (robots already waiting on the same side).
  int slot = 0;
  for (; slot < 10; ++slot) {
    const PlanarPose cand = sidelinePose(world.field(), team, from.y, slot);
    bool clash = false;
    for (const auto& [other, t] : taken_)
      if (other != robot && std::abs(t.to.x - cand.x) < 1e-6 && std::abs(t.to.y - cand.y) < 1e-6) clash = true;
    if (!clash) break;
  }
  const PlanarPose to = sidelinePose(world.field(), team, from.y, slot);
  if (!taken_.count(robot)) taken_[robot] = {from, to, team};
  world.placeRobot(robot, to.x, to.y, to.theta, posture_);
  return to;
}

void PenaltyPlacer::unpenalise(World& world, int robot, bool restore) {
  auto it = taken_.find(robot);
  if (it == taken_.end()) return;
  if (restore) world.placeRobot(robot, it->second.from.x, it->second.from.y, it->second.from.theta, posture_);
  taken_.erase(it);
}

}  // namespace simswift::game
