// The Blackboard's sections as types. Each section holds one representation
// type (agent/blackboard/), so a module names what it reads and writes by
// type; SectionOf<T> gives that section's id, its name (the Blackboard's
// field name) and the field itself.
#pragma once

#include "agent/blackboard/Blackboard.hpp"

namespace agent::framework {

// One id per Blackboard section, named as its field.
enum class SectionId : int {
  Sensors = 0,
  Frame,
  Vision,
  Localisation,
  Ball,
  Team,
  Game,
  GameController,
  TeamInbox,
  TeamOutbox,
  MotionRequest,
  FindBall,
  Motion,
  Actuators,
  NUM_SECTIONS
};
constexpr int kNumSections = static_cast<int>(SectionId::NUM_SECTIONS);
const char* sectionName(SectionId s);

template <class T>
struct SectionOf;  // defined for each representation a Blackboard section holds

#define SIMSWIFT_SECTION(Type, Id, field)                                                   \
  template <>                                                                                \
  struct SectionOf<blackboard::Type> {                                                       \
    static constexpr SectionId id = SectionId::Id;                                           \
    static blackboard::Section<blackboard::Type>& of(blackboard::Blackboard& b) { return b.field; } \
  };
SIMSWIFT_SECTION(SensorFrame, Sensors, sensors)
SIMSWIFT_SECTION(FrameInfo, Frame, frame)
SIMSWIFT_SECTION(VisionMeasurements, Vision, vision)
SIMSWIFT_SECTION(LocalisationEstimate, Localisation, localisation)
SIMSWIFT_SECTION(BallEstimate, Ball, ball)
SIMSWIFT_SECTION(TeamInfo, Team, team)
SIMSWIFT_SECTION(GameInfo, Game, game)
SIMSWIFT_SECTION(GameControllerData, GameController, game_controller)
SIMSWIFT_SECTION(TeamInbox, TeamInbox, team_inbox)
SIMSWIFT_SECTION(TeamOutbox, TeamOutbox, team_outbox)
SIMSWIFT_SECTION(MotionRequest, MotionRequest, motion_request)
SIMSWIFT_SECTION(FindBallInfo, FindBall, findball)
SIMSWIFT_SECTION(MotionState, Motion, motion)
SIMSWIFT_SECTION(ActuatorRequest, Actuators, actuators)
#undef SIMSWIFT_SECTION

}  // namespace agent::framework
