// Behaviour stand-in for scenarios and tests: a timed list of body actions
// (walk at forward/left/turn, stand, kick, ...) written to the Blackboard's
// MotionRequest as simulated time passes, in front of a MotionModule. It
// runs inside the Motion tick, so it is as deterministic as the tick.
// Units: s, mm/s, rad/s, rad.
#pragma once

#include <memory>
#include <vector>

#include "agent/blackboard/Blackboard.hpp"
#include "agent/motion/MotionModule.hpp"
#include "agent/program/MotionGenerator.hpp"

namespace agent::motion {

struct ActionStep {
  double t = 0;                   // s of simulated time at which it is requested
  blackboard::BodyCommand body;   // body.type = the action
  bool has_head = false;
  blackboard::HeadCommand head;
};

class ActionScriptMotion : public agent::program::MotionGenerator {
 public:
  // Steps are sorted by time here; the first applies at its t.
  explicit ActionScriptMotion(std::vector<ActionStep> steps, const MotionConfig& cfg = MotionConfig());

  void tick(const libagent::SensorValues& sensors, int64_t sim_time_us, libagent::JointValues& out) override;

  blackboard::Blackboard& board() { return board_; }
  MotionModule& module() { return *module_; }

 private:
  blackboard::Blackboard board_;
  std::unique_ptr<MotionModule> module_;
  std::vector<ActionStep> steps_;
  size_t next_ = 0;
};

// Parses an action name ("walk", "stand", "kick", "getup_front", "getup_back",
// "dead", "crouch", "limp", "none"); false if unknown.
bool parseActionType(const std::string& name, blackboard::ActionType* out);

}  // namespace agent::motion
