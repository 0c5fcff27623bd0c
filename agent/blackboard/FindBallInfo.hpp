// What the behaviour module publishes each Perception frame (the thesis's
// "findball" Blackboard entry, 4.2): the FindBall class's distributions and
// choice, the search point the behaviour is heading to, what it knows of its
// teammates' searches (for the FindBall view), and this robot's
// SearchPayload bytes for the team packet's free data area (team send).
// Units: mm, rad, s; field frame (Localisation.hpp).
#pragma once

#include <cstdint>
#include <vector>

namespace agent::blackboard {

struct FindBallTeammate {
  int32_t player = 0;
  double x = 0, y = 0, theta = 0;  // mm, mm, rad: where it says it is
  bool has_target = false;         // its packet names a search point
  double target_x = 0, target_y = 0;  // mm
  int32_t segment = -1;            // 0-based, -1 none
};

struct FindBallInfo {
  bool active = false;         // a behaviour module runs (false: nothing below is meaningful)
  int32_t kind = 0;            // agent::behaviour::BehaviourKind
  double time = 0;             // s, frame time
  char activity[32] = {};      // what the role does now ("findball2017", "penalised", ...)
  // The FindBall class's distributions (2017 and striker; uniform for 2016):
  // columns x rows, row by row from the top-left (most negative x, most
  // positive y), as agent::behaviour::PositionalDistribution. Sum to 1.
  int32_t columns = 3, rows = 3;
  std::vector<double> team;    // the team (combined) distribution the strategy uses
  std::vector<double> local;   // this robot's own, sent to teammates
  int64_t resets = 0;          // frames on which the local distribution was uniform after not being so
  // The search target: the segment the 2017 search heads to (-1: none) and
  // the point the active search walks to.
  int32_t segment = -1;
  bool has_point = false;
  double point_x = 0, point_y = 0;  // mm
  double pose_x = 0, pose_y = 0, pose_theta = 0;  // mm, rad: the pose the behaviour used
  std::vector<FindBallTeammate> teammates;
  // SearchPayload bytes for the SPL message's data area (empty: send none).
  std::vector<uint8_t> payload;
};

}  // namespace agent::blackboard
