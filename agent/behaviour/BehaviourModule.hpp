// The behaviour as a Perception module (last but one in the Perception
// thread's order: ... ball tracker -> team receive -> behaviour -> team send).
//
// Each camera frame it fills BehaviourInputs from the Blackboard (inputsFrom,
// below), runs the Behaviour (agent/behaviour/Behaviour.hpp: 2016 FindBall,
// the 2017 ball searching component, or the striker) and writes
//   motion_request: body and head command (Motion reads it each 10 ms tick);
//   findball:       distributions, choice, teammates' targets and this robot's
//                   SearchPayload bytes (team send puts them into the SPL
//                   message's free data area; the FindBall view draws the rest).
// Units: mm, rad, s; field frame.
#pragma once

#include "agent/behaviour/Behaviour.hpp"
#include "agent/blackboard/FindBallInfo.hpp"
#include "agent/behaviour/BehaviourInputs.hpp"
#include "agent/behaviour/SonarFilter.hpp"
#include "agent/blackboard/FrameInfo.hpp"
#include "agent/framework/Module.hpp"

namespace agent::behaviour {

struct BehaviourModuleConfig {
  BehaviourConfig behaviour;
  WalkLimits walk;  // the walk's achieved top speeds (its calibrated maxima, agent/motion/WalkConfig.hpp)
  int team = 0, player = 2;
};

// A teammate as the Blackboard's findball section records it (the one
// conversion: the module writes it, the FindBall view draws from it).
blackboard::FindBallTeammate findBallTeammate(const Teammate& t);

class BehaviourModule
    : public framework::ModuleOf<framework::Reads<blackboard::FrameInfo, blackboard::LocalisationEstimate,
                                                  blackboard::BallEstimate, blackboard::TeamInfo,
                                                  blackboard::GameInfo, blackboard::MotionState,
                                                  blackboard::SensorFrame>,
                                 framework::Writes<blackboard::MotionRequest, blackboard::FindBallInfo>> {
 public:
  explicit BehaviourModule(const BehaviourModuleConfig& c)
      : c_(c), behaviour_(c.behaviour), sonar_(c.behaviour.skills) {}
  const char* name() const override { return "behaviour"; }
  const Behaviour& behaviour() const { return behaviour_; }

 private:
  void update(const In& in, Out& out) override;
  // The Blackboard's view of the world as behaviour inputs. Teammates come
  // from team receive's reports (this robot excluded), their free data
  // decoded as a SearchPayload (malformed: no search data).
  BehaviourInputs inputsFrom(const In& board) const;
  BehaviourModuleConfig c_;
  Behaviour behaviour_;
  SonarFilter sonar_;  // the chest sonars over frames (inputs' sonar)
  bool was_uniform_ = true;
  int64_t resets_ = 0;
};

}  // namespace agent::behaviour
