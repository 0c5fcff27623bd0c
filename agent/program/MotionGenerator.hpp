// The Motion thread's replaceable step. Once per 10 ms tick the robot program
// hands a generator the latest sensors and the simulated time and sends the
// joint command it fills (angles rad, stiffnesses 0..1 or -1 limp). The walk
// (agent/motion/) plugs in here as another generator.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "agent/libagent/AgentShared.hpp"
#include "agent/libagent/CameraImages.hpp"
#include "agent/libagent/CameraShared.hpp"
#include "agent/program/Postures.hpp"

namespace agent::program {

class MotionGenerator {
 public:
  virtual ~MotionGenerator() = default;
  // `out` arrives holding the previous command (the posture it started from
  // on the first tick); fill angles and stiffnesses.
  virtual void tick(const agent::libagent::SensorValues& sensors, int64_t sim_time_us,
                    agent::libagent::JointValues& out) = 0;
};

// Holds one posture.
class PoseGenerator : public MotionGenerator {
 public:
  explicit PoseGenerator(Posture p) : cmd_(postureCommand(p)) {}
  explicit PoseGenerator(const agent::libagent::JointValues& cmd) : cmd_(cmd) {}
  void tick(const agent::libagent::SensorValues&, int64_t, agent::libagent::JointValues& out) override {
    out = cmd_;
  }

 private:
  agent::libagent::JointValues cmd_;
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
class ScriptedMotion : public MotionGenerator {
 public:
  ScriptedMotion(Posture start, std::vector<ScriptStep> steps = {});
  void tick(const agent::libagent::SensorValues& sensors, int64_t sim_time_us,
            agent::libagent::JointValues& out) override;
  void setAnkleGyroDamping(float gain_s) { ankle_gain_ = gain_s; }

 private:
  float ankle_gain_ = 0;     // s
  float gyro_filtered_ = 0;  // rad/s
  struct Ramp { int joint; float from, to; double t0, t1; };
  agent::libagent::JointValues cmd_;
  std::vector<ScriptStep> steps_;
  std::vector<Ramp> ramps_;
  size_t next_ = 0;
};

// An extra Perception step for tests and tools (e.g. reading the rendered
// images): run first in the Perception thread with each camera frame.
class PerceptionStep {
 public:
  virtual ~PerceptionStep() = default;
  virtual void step(const agent::libagent::CameraFrame& frame) { ++frames_; }
  int64_t frames() const { return frames_; }
  // The rendered images (null unless the simulator renders); hold the frame
  // passed to step() when frame.images_valid is 1. Set by RobotProgram.
  void setImages(const agent::libagent::CameraImages* images) { images_ = images; }
  const agent::libagent::CameraImages* images() const { return images_; }

 protected:
  int64_t frames_ = 0;
  const agent::libagent::CameraImages* images_ = nullptr;
};

}  // namespace agent::program
