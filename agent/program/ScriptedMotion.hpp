// The robot program's own motion generators (agent/framework/MotionGenerator.hpp):
// a held posture and a joint script.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "agent/framework/MotionGenerator.hpp"
#include "common/libagent/AgentShared.hpp"
#include "agent/program/Postures.hpp"

namespace agent::program {

// Holds one posture.
class PoseGenerator : public framework::MotionGenerator {
 public:
  explicit PoseGenerator(Posture p) : cmd_(postureCommand(p)) {}
  explicit PoseGenerator(const common::libagent::JointValues& cmd) : cmd_(cmd) {}
  void tick(const common::libagent::SensorValues&, int64_t, common::libagent::JointValues& out) override {
    out = cmd_;
  }

 private:
  common::libagent::JointValues cmd_;
};

// One scripted change at simulated time t_s: either one joint moves to
// `angle` (rad, reached linearly over `duration_s`, 0 = at once; the servo's
// speed limit still applies) with optional new stiffness, or the whole body
// switches posture.
struct ScriptStep {
  double t_s = 0;
  int joint = -1;            // libagent index; -1 = posture step
  float angle = 0;           // rad
  float stiffness = -2;      // < -1 = keep
  double duration_s = 0;
  Posture posture = Posture::Stand;
};

// Holds a posture and applies script steps in time order.
//
// Optional ankle damping: a small closed loop that adds
// gain * (low-passed GyroscopeY) to both AnklePitch targets (rad, gain in s).
// A torso pitching forward (GyroscopeY > 0) then pushes the toes down, which
// resists the pitch. It is what makes a standing robot's physics depend on
// its sensors (and so on the noise seed), as on a real robot.
class ScriptedMotion : public framework::MotionGenerator {
 public:
  ScriptedMotion(Posture start, std::vector<ScriptStep> steps = {});
  void tick(const common::libagent::SensorValues& sensors, int64_t sim_time_us,
            common::libagent::JointValues& out) override;
  void setAnkleGyroDamping(float gain_s) { ankle_gain_ = gain_s; }

 private:
  float ankle_gain_ = 0;     // s
  float gyro_filtered_ = 0;  // rad/s
  struct Ramp { int joint; float from, to; double t0, t1; };
  common::libagent::JointValues cmd_;
  std::vector<ScriptStep> steps_;
  std::vector<Ramp> ramps_;
  size_t next_ = 0;
};

}  // namespace agent::program
