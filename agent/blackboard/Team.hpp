// What teammates last said (team receive writes it; behaviour, the ball
// tracker and team send read it). Units: mm, rad, s; field frame.
#pragma once

#include <cstdint>
#include <vector>

namespace agent::blackboard {

constexpr int kMaxTeammates = 6;  // players 1..6

struct TeammateReport {
  bool valid = false;
  int32_t player = 0;
  double received = -1;            // s, our frame time of reception
  bool fallen = false;
  double x = 0, y = 0, theta = 0;  // mm, mm, rad: where they think they are
  double ball_x = 0, ball_y = 0;   // mm, field: their ball
  double ball_vx = 0, ball_vy = 0; // mm/s
  double ball_age = 1e9;           // s since they saw the ball when sent
  std::vector<uint8_t> data;       // the packet's free data area (the behaviour decodes it)
};

struct TeamInfo {
  int32_t team_number = 0;
  int32_t player_number = 0;
  TeammateReport mates[kMaxTeammates + 1];  // indexed by player number (0 unused)
  int64_t received = 0;   // packets accepted
  int64_t malformed = 0;  // packets dropped as malformed
};

}  // namespace agent::blackboard
