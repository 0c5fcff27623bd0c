// The Blackboard: the store the robot program's threads share. One per
// robot program, owned by RobotProgram.
//
// It is split into sections, one per producing module. Each section is a
// plain value struct guarded by its own mutex (Section<T>); readers take a
// copy, writers replace the value under the lock, so a thread never sees
// half of another thread's write and never holds a lock while it computes.
// Most sections are a few hundred bytes; the largest, frame (FrameInfo: the
// camera frame's observations, ~4.2 KB) and findball (the search grids), are
// copied once per 33 ms camera frame.
//
// Who reads and writes what is declared by the modules' types
// (agent/framework/Module.hpp) and checked at start-up
// (agent/framework/ModuleSchedule.hpp); the order per thread is in
// agent/program/ModuleOrder.cpp. The sections are SIMSWIFT_BLACKBOARD_SECTIONS
// below, the one list the Blackboard's fields, the framework's SectionId,
// section names and SectionOf<T> are generated from.
//
// Units: distances mm, speeds mm/s, angles rad, angular speeds rad/s.
// Frames: sensors, vision and the motion request are robot-relative (x
// forward, y left, z up, as on the NAO); localisation, ball (x, y), team and
// findball are in the field frame (x toward the opponent goal, origin at the
// centre); each struct says which.
#pragma once

#include <cstdint>
#include <cstring>
#include <mutex>

#include "agent/blackboard/Ball.hpp"
#include "agent/blackboard/Extensions.hpp"
#include "agent/blackboard/FindBallInfo.hpp"
#include "agent/blackboard/FrameInfo.hpp"
#include "agent/blackboard/GameInfo.hpp"
#include "agent/blackboard/Localisation.hpp"
#include "agent/blackboard/Odometry.hpp"
#include "agent/blackboard/Team.hpp"
#include "agent/blackboard/Vision.hpp"
#include "common/libagent/AgentShared.hpp"

namespace agent::blackboard {

// A value guarded by its own mutex. read() returns a copy; write() replaces.
template <typename T>
class Section {
 public:
  T read() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return value_;
  }
  void write(const T& v) {
    std::lock_guard<std::mutex> lock(mutex_);
    value_ = v;
  }
  // Read-modify-write under the lock: fn(T&).
  template <typename Fn>
  void update(Fn&& fn) {
    std::lock_guard<std::mutex> lock(mutex_);
    fn(value_);
  }

 private:
  mutable std::mutex mutex_;
  T value_{};
};

// ---------------------------------------------------------------- requests

// What the body should do. The Motion thread picks the generator from this.
enum class ActionType : int32_t {
  NONE = 0,     // keep doing what is being done (no new body request)
  STAND,        // stand still, knees slightly bent (the walk's stand)
  WALK,         // omnidirectional walk at forward/left/turn
  KICK,         // kick with `foot` at `kick_power` toward `kick_direction`
  GETUP_FRONT,  // get up from lying face down
  GETUP_BACK,   // get up from lying on the back
  DEAD,         // fall-safe: all joints limp (stiffness off)
  CROUCH,       // low crouch, low stiffness (safe rest posture)
  LIMP,         // low stiffness, holding the current angles loosely
  NUM_ACTION_TYPES
};
const char* actionName(ActionType t);

enum class Foot : int32_t { LEFT = 0, RIGHT = 1 };

struct HeadCommand {
  float yaw = 0;          // rad, + = left
  float pitch = 0;        // rad, + = down
  bool relative = false;  // true: yaw/pitch are added to the current angles
  float yaw_speed = 1.0f;    // rad/s, limited further by the joint's max speed
  float pitch_speed = 1.0f;  // rad/s
};

struct BodyCommand {
  ActionType type = ActionType::NONE;
  float forward = 0;          // mm/s (WALK)
  float left = 0;             // mm/s (WALK)
  float turn = 0;             // rad/s, + = counter-clockwise (WALK)
  float kick_power = 1.0f;    // 0..1 (KICK)
  float kick_direction = 0;   // rad, robot-relative, 0 = straight ahead (KICK)
  Foot foot = Foot::RIGHT;    // kicking foot (KICK)
};

// Written by Behaviour (or a scenario script), read by Motion.
struct MotionRequest {
  HeadCommand head;
  BodyCommand body;
  common::libagent::LedCommand leds{};
  int64_t sequence = 0;  // incremented by the writer on every new request
};

// ---------------------------------------------------------------- outputs

// What the body is doing, as Motion sees it. (Not a joint pose: those are
// agent::program::Posture, the stand / crouch / limp poses a program holds.)
enum class BodyState : int32_t {
  STANDING = 0,
  WALKING,
  KICKING,
  GETTING_UP,
  FALLING,          // a fall was detected, joints made limp
  FALLEN_FORWARD,   // lying face down
  FALLEN_BACKWARD,  // lying on the back
  FALLEN_SIDEWAYS,
  LIMP,             // DEAD / LIMP / CROUCH on request
};

// Written by Motion, read by everyone.
struct MotionState {
  Odometry odometry;
  BodyState posture = BodyState::STANDING;
  Foot support_foot = Foot::LEFT;
  ActionType active = ActionType::NONE;  // the generator currently running
  bool walk_stepping = false;            // the walk is taking steps
  int64_t request_sequence = 0;          // last MotionRequest::sequence seen
  int64_t tick = 0;                      // Motion ticks so far
  double time = 0;                       // s, sim time of the last tick
};

// ---------------------------------------------------------------- the store

// The joint command Motion computed this tick (the effector sends it).
struct ActuatorRequest {
  common::libagent::JointValues joints{};  // angles rad, stiffnesses 0..1 (-1 limp)
  common::libagent::LedCommand leds{};
  int64_t tick = 0;
};

// The sections, in order: X(type, SectionId enumerator, field = section name),
// each with its writer -> readers. The order is the Blackboard's field order
// and SectionId's numbering.
#define SIMSWIFT_BLACKBOARD_SECTIONS(X)                                                                         \
  X(SensorFrame, Sensors, sensors)             /* program, every Motion tick -> motion */                       \
  X(FrameInfo, Frame, frame)                   /* program, every camera frame -> every Perception module */     \
  X(VisionMeasurements, Vision, vision)        /* vision adapter -> localisation, ball tracker */               \
  X(LocalisationEstimate, Localisation, localisation) /* localisation -> ball tracker, behaviour, team send */   \
  X(BallEstimate, Ball, ball)                  /* ball tracker -> behaviour, team send */                       \
  X(TeamInfo, Team, team)                      /* team receive -> ball tracker (previous frame), behaviour */   \
  X(GameInfo, Game, game)                      /* game state -> localisation, behaviour, action script */       \
  X(GameControllerData, GameController, game_controller) /* program (game-state device), every camera frame    \
                                                            -> game state */                                    \
  X(TeamInbox, TeamInbox, team_inbox)          /* program (team transport), every camera frame -> team receive */ \
  X(TeamOutbox, TeamOutbox, team_outbox)       /* team send -> program (puts it on the team transport) */       \
  X(MotionRequest, MotionRequest, motion_request) /* behaviour or a scenario's action script -> motion */       \
  X(FindBallInfo, FindBall, findball)          /* behaviour -> team send, the simulator's FindBall view */      \
  X(MotionState, Motion, motion)               /* motion -> vision adapter, localisation, ball tracker,         \
                                                  behaviour, team send */                                       \
  X(ActuatorRequest, Actuators, actuators)     /* motion -> effector */

// The store: one Section per entry of the list above, in its order.
struct Blackboard {
#define SIMSWIFT_BLACKBOARD_FIELD(Type, Id, field) Section<Type> field;
  SIMSWIFT_BLACKBOARD_SECTIONS(SIMSWIFT_BLACKBOARD_FIELD)
#undef SIMSWIFT_BLACKBOARD_FIELD
};

inline const char* actionName(ActionType t) {
  switch (t) {
    case ActionType::NONE: return "NONE";
    case ActionType::STAND: return "STAND";
    case ActionType::WALK: return "WALK";
    case ActionType::KICK: return "KICK";
    case ActionType::GETUP_FRONT: return "GETUP_FRONT";
    case ActionType::GETUP_BACK: return "GETUP_BACK";
    case ActionType::DEAD: return "DEAD";
    case ActionType::CROUCH: return "CROUCH";
    case ActionType::LIMP: return "LIMP";
    default: return "?";
  }
}

inline const char* bodyStateName(BodyState p) {
  switch (p) {
    case BodyState::STANDING: return "STANDING";
    case BodyState::WALKING: return "WALKING";
    case BodyState::KICKING: return "KICKING";
    case BodyState::GETTING_UP: return "GETTING_UP";
    case BodyState::FALLING: return "FALLING";
    case BodyState::FALLEN_FORWARD: return "FALLEN_FORWARD";
    case BodyState::FALLEN_BACKWARD: return "FALLEN_BACKWARD";
    case BodyState::FALLEN_SIDEWAYS: return "FALLEN_SIDEWAYS";
    case BodyState::LIMP: return "LIMP";
  }
  return "?";
}

}  // namespace agent::blackboard
