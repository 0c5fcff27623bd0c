// The Motion module driven without a Behaviour: a test, bench or tool sets
// the motion request (from any thread; each tick takes the latest) and reads
// the motion state back, with the module running as the program's motion
// generator. The robot program's own path is MotionThreadModule
// (agent/program/StandardModules.hpp), which takes the request from the
// Blackboard; both run the same MotionModule::tick.
#pragma once

#include "agent/blackboard/Blackboard.hpp"
#include "agent/framework/MotionGenerator.hpp"
#include "agent/motion/MotionModule.hpp"

namespace agent::motion {

class RequestedMotion : public framework::MotionGenerator {
 public:
  explicit RequestedMotion(const MotionConfig& cfg = MotionConfig()) : motion_(cfg) {}

  // Read-modify-write of the request under its lock: fn(MotionRequest&).
  template <typename Fn>
  void request(Fn&& fn) {
    request_.update(fn);
  }
  blackboard::MotionState state() const { return state_.read(); }
  MotionModule& module() { return motion_; }

  void tick(const libagent::SensorValues& sensors, int64_t sim_time_us, libagent::JointValues& out) override {
    motion_.setRequest(request_.read());
    motion_.tick(sensors, sim_time_us, out);
    state_.write(motion_.state());
  }

 private:
  MotionModule motion_;
  blackboard::Section<blackboard::MotionRequest> request_;
  blackboard::Section<blackboard::MotionState> state_;
};

}  // namespace agent::motion
