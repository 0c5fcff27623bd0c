// Kick skill: a KICK request toward the kick target with the foot on the
// ball's side, held for kick_duration s (Motion runs the kick once).
#pragma once

#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/behaviour/BehaviourInputs.hpp"
#include "agent/blackboard/Blackboard.hpp"

namespace agent::behaviour {

class Kick {
 public:
  explicit Kick(const SkillConfig& s) : s_(s) {}
  void start(const BehaviourInputs& in);
  struct Output {
    blackboard::BodyCommand body;
    bool done = false;
  };
  Output tick(const BehaviourInputs& in) const;

 private:
  SkillConfig s_;
  double start_ = 0;
  blackboard::BodyCommand cmd_;
};

}  // namespace agent::behaviour
