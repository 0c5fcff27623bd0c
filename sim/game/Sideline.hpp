// Where a penalised robot stands: on the touch line (the sideline), level
// with its own half's penalty mark, facing into the field (SPL rules; the
// thesis's experiments also start robots penalised at the side of the field).
// Team 0 defends the goal at -x, team 1 the goal at +x (field frame, m, rad).
// PenaltyPlacer moves robots there through World::placeRobot and back.
#pragma once

#include <map>
#include <vector>

#include "sim/world/FieldConfig.hpp"
#include "sim/world/World.hpp"

namespace simswift::game {

struct PlanarPose { double x = 0, y = 0, theta = 0; };  // m, m, rad; field frame

constexpr double kPenaltyMarkFromGoalLine = 1.3;  // m, SPL 2017 field
constexpr double kSidelineSpacing = 0.4;          // m between robots waiting at one spot

// The sideline spot for a robot of `team` now at `y` (the nearer touch line;
// y = 0 takes +y). `slot` > 0 moves it that many spacings towards the centre
// line, so penalised teammates do not stand in one another.
PlanarPose sidelinePose(const FieldConfig& field, int team, double y, int slot = 0);

// The robot's torso position and heading in the field frame (m, rad).
PlanarPose robotPose(const World& world, int robot);

class PenaltyPlacer {
 public:
  // `posture`: model joint order, the robot is set down in it (standing).
  explicit PenaltyPlacer(std::vector<double> posture) : posture_(std::move(posture)) {}
  // Remembers where robot `robot` of `team` is, then puts it on the sideline.
  PlanarPose penalise(World& world, int robot, int team);
  // Back to where penalise() took it from (restore = true) or left where it is.
  void unpenalise(World& world, int robot, bool restore);
  bool holds(int robot) const { return taken_.count(robot) != 0; }

 private:
  struct Taken { PlanarPose from, to; int team; };
  std::vector<double> posture_;
  std::map<int, Taken> taken_;  // robot index -> where from and to
};

}  // namespace simswift::game
