// The ball tracker's estimate, robot-relative and on the field, with the
// time since the robot last saw it, plus the team ball (teammates' reports).
// Units: mm, mm/s, s. Robot-relative: x forward, y left. Field: as in
// Localisation.hpp.
#pragma once

#include <cstdint>

namespace agent::blackboard {

struct BallEstimate {
  bool valid = false;          // this robot tracks a ball (seen within the tracker's lost_after);
                               // if not, x/y and rr_x/rr_y hold the team ball when team_valid
  double rr_x = 0, rr_y = 0;   // mm, robot-relative position
  double rr_vx = 0, rr_vy = 0; // mm/s, robot-relative velocity (robot frame, not
                               // counting the robot's own motion)
  double x = 0, y = 0;         // mm, field position (through the pose estimate)
  double vx = 0, vy = 0;       // mm/s, field velocity
  double sd_position = 0;      // mm, 1 sigma of the position
  double time_since_seen = 1e9;  // s since this robot last saw it
  bool seen_this_frame = false;

  // Team ball: the freshest report among teammates who saw it recently.
  bool team_valid = false;
  double team_x = 0, team_y = 0;  // mm, field
  double team_age = 1e9;          // s since that teammate saw it
  int32_t team_player = -1;       // who reported it
  double time = 0;                // s, frame time of this estimate
};

}  // namespace agent::blackboard
