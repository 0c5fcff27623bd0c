// The Motion thread's replaceable step. Once per 10 ms tick the robot program
// hands a generator the latest sensors and the simulated time and sends the
// joint command it fills (angles rad, stiffnesses 0..1 or -1 limp). The
// Motion module (agent/motion/ActionMotion) is one; the program's held
// postures and joint scripts (agent/program/ScriptedMotion.hpp) are others.
#pragma once

#include <cstdint>

#include "common/libagent/AgentShared.hpp"

namespace agent::framework {

class MotionGenerator {
 public:
  virtual ~MotionGenerator() = default;
  // `out` arrives holding the previous command (the posture it started from
  // on the first tick); fill angles and stiffnesses.
  virtual void tick(const common::libagent::SensorValues& sensors, int64_t sim_time_us,
                    common::libagent::JointValues& out) = 0;
};

}  // namespace agent::framework
