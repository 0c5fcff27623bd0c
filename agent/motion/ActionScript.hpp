// A timed list of body actions (walk at forward/left/turn, stand, kick, ...):
// what a scenario's or a setup file's `actions:` say, and the action names.
// agent/behaviour/ActionsBehaviour.hpp plays the list. Units: s, mm/s,
// rad/s, rad.
#pragma once

#include <string>
#include <vector>

#include "agent/blackboard/Blackboard.hpp"

namespace agent::motion {

struct ActionStep {
  double t = 0;                   // s of simulated time at which it is requested
  blackboard::BodyCommand body;   // body.type = the action
  bool has_head = false;
  blackboard::HeadCommand head;
};

// Parses an action name ("walk", "stand", "kick", "getup_front", "getup_back",
// "dead", "crouch", "limp", "none"); false if unknown.
bool parseActionType(const std::string& name, blackboard::ActionType* out);

}  // namespace agent::motion
