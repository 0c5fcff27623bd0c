// Everything the behaviour reads, as plain structs with units. Perception
// (localisation, ball tracker, team communication, game controller) fills
// one of these per behaviour tick; the behaviour never reads anything else,
// so it can be driven by the Blackboard on the robot or by a test directly.
//
// Units: mm, mm/s, rad, rad/s, s. "Field" = field frame (see Geometry.hpp),
// "robot-relative" = x forward, y left from the robot's centre on the ground.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "agent/behaviour/Geometry.hpp"
#include "agent/behaviour/SearchPayload.hpp"
#include "agent/motion/WalkConfig.hpp"

namespace agent::behaviour {

// This robot's localisation estimate.
struct SelfState {
  Pose2 pose;                 // field frame, mm/mm/rad
  double confidence = 1.0;    // 0 (lost) .. 1 (certain)
  bool flipped = false;       // localisation detected a flip (mislocalisation) this tick
  bool fallen = false;        // lying or getting up
};

// This robot's own ball estimate (ball tracker).
struct OwnBall {
  bool ever_seen = false;        // false: the rest is meaningless
  bool seen_now = false;         // detected in this tick's camera frames
  double time_since_seen = 1e9;  // s since the last detection
  Point2 relative;               // robot-relative estimate, mm
  Point2 field;                  // field-frame estimate, mm
};

// The team's shared ball (from teammates' packets).
struct TeamBall {
  bool valid = false;            // some teammate has seen the ball recently
  double time_since_seen = 1e9;  // s since the freshest teammate sighting
  Point2 field;                  // mm
};

// One teammate, as heard in its last team packet.
struct Teammate {
  int player = 0;                // player number 1..6
  Pose2 pose;                    // field frame
  bool fallen = false;
  bool penalised = false;
  bool sees_ball = false;        // the teammate saw the ball in its last packet
  double time_since_heard = 1e9; // s since its last packet
  // Its FindBall data (local distribution, chosen segment/point), decoded
  // from the packet's free data area; empty if absent or malformed.
  std::optional<SearchPayload> search;
};

enum class GameState : int32_t { INITIAL = 0, READY, SET, PLAYING, FINISHED };

struct GameInfo {
  GameState state = GameState::PLAYING;
  bool penalised = false;  // this robot is penalised
};

// The walk's real (achieved) top speeds, for planning and travel times.
// Defaults: the walk's own limits (one home: agent/motion/WalkConfig.hpp).
struct WalkLimits {
  double max_forward = motion::WalkConfig{}.max_forward;  // mm/s
  double max_left = motion::WalkConfig{}.max_left;        // mm/s
  double max_turn = motion::WalkConfig{}.max_turn;        // rad/s
};

// The chest sonars' first echoes as the behaviour sees them: the nearest
// echo of each side (mm; no echo: the NAO's 2.55 m) and whether that side
// counts as having an object close by (SonarFilter, over frames).
struct SonarState {
  double left = 2550, right = 2550;  // mm
  bool near_left = false, near_right = false;
};

struct BehaviourInputs {
  double time = 0;        // s, simulated time of this tick (monotonic)
  int player = 2;         // this robot's player number
  SelfState self;
  OwnBall ball;
  TeamBall team_ball;
  std::vector<Teammate> teammates;  // this robot excluded
  GameInfo game;
  WalkLimits walk;
  SonarState sonar;
};

}  // namespace agent::behaviour
