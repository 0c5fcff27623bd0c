// The actions behaviour for scenarios and tests: a timed list of body actions
// (walk at forward/left/turn, stand, kick, ...) written to the Blackboard's
// motion request as simulated time passes. It is a Behaviour module in
// the Perception thread (30 Hz, frame time), so a scripted robot and a
// behaving robot reach Motion by the same path. Like any behaviour it obeys
// the game: while the robot is penalised, or the game is INITIAL, SET or
// FINISHED, it asks Motion to stand; when released the script's current
// action resumes.
// Units: s, mm/s, rad/s, rad.
#pragma once

#include <vector>

#include "agent/blackboard/Blackboard.hpp"
#include "agent/framework/Module.hpp"
#include "agent/motion/ActionScript.hpp"

namespace agent::behaviour {

using motion::ActionStep;

// frame (time) + game -> motion request.
class ActionsBehaviour
    : public framework::ModuleOf<framework::Reads<blackboard::FrameInfo, blackboard::GameInfo>,
                                 framework::Writes<blackboard::MotionRequest>> {
 public:
  // Steps are sorted by time here; each applies at the first frame at or
  // after its t. Until the first: STAND.
  explicit ActionsBehaviour(std::vector<ActionStep> steps);

  const char* name() const override { return "behaviour (action script)"; }

 private:
  void update(const In& in, Out& out) override;
  static void request(blackboard::MotionRequest& r, const blackboard::BodyCommand& body,
                      const blackboard::HeadCommand* head);
  blackboard::BodyCommand current_;  // the script's action now (STAND before the first)
  bool held_ = false;                // standing for the game (penalty, INITIAL/SET/FINISHED)
  std::vector<ActionStep> steps_;
  size_t next_ = 0;
  bool started_ = false;
};

}  // namespace agent::behaviour
