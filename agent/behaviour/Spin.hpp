// Spin skill: a turn on the spot of angle() rad of heading (counted from the
// localisation heading; SkillConfig::spin_angle, by default what completes
// the circle a head scan began), head straight ahead and slightly down.
#pragma once

#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/behaviour/BehaviourInputs.hpp"
#include "agent/blackboard/Blackboard.hpp"

namespace agent::behaviour {

class Spin {
 public:
  explicit Spin(const SkillConfig& s) : s_(s) {}
  void start(const Pose2& pose) {
    last_theta_ = pose.theta;
    turned_ = 0;
  }
  struct Output {
    blackboard::BodyCommand body;
    blackboard::HeadCommand head;
    bool done = false;
  };
  Output tick(const BehaviourInputs& in);
  double turned() const { return turned_; }  // rad so far
  double angle() const;                      // rad to turn in all

 private:
  SkillConfig s_;
  double last_theta_ = 0;
  double turned_ = 0;
};

}  // namespace agent::behaviour
