// What a scenario test's predicates read: the world's truth after a tick
// (never a robot's belief). One snapshot per tick, taken by observe().
#pragma once

#include <cstdint>
#include <vector>

#include "common/libagent/GameState.hpp"
#include "sim/world/FieldConfig.hpp"

namespace simswift::runner {
class Runner;
}

namespace simswift::scenario_tests {

struct RobotTruth {
  int side = 0;                // 0 blue (own goal at -x), 1 red (own goal at +x)
  double x = 0, y = 0;         // m, field frame: the torso's origin
  double heading = 0;          // rad
  bool fallen = false;         // torso below the fall height (runner::FallDetector)
  int falls = 0;               // falls so far
  bool penalised = false;      // by the GameController
  bool touched_ball = false;   // a link of the robot touched the ball at some tick so far
};

struct Truth {
  double t = 0;                     // s since the test's start
  bool has_ball = false;
  double ball_x = 0, ball_y = 0, ball_z = 0;  // m, field frame (centre)
  std::vector<RobotTruth> robots;   // scenario order
  common::libagent::GameStateValue state = common::libagent::GameStateValue::Playing;
  int64_t team_sent[2] = {0, 0};    // team packets each side's programs sent so far (over budget too)
};

// The truth after the runner's latest tick, t s since the start; `before`
// (the previous snapshot, or null) carries what is cumulative (touches).
Truth observe(runner::Runner& r, double t, const Truth* before);

// Whether the whole ball is over a goal line between the posts and under
// the crossbar: side 0 the goal blue defends (-x), 1 red's (+x).
bool ballInGoal(const Truth& t, const FieldConfig& f, int side);

}  // namespace simswift::scenario_tests
