// The builtin robot program (agent/program/RobotProgram) in this process,
// attached to its body through an in-process libagent block: on its own
// named threads (ThreadedProgram, the default; gdb, `simswift run`) or
// stepped on the simulator's thread (InlineProgram: the experiment, the
// benchmarks, the public API) -- the same steps in the same order, the same
// state hash (tests/runner/test_determinism.cpp). ApiController is an inline
// program whose Motion step is the public API's controller.
#pragma once

#include <functional>
#include <memory>

#include "agent/framework/MotionGenerator.hpp"
#include "common/libagent/AgentShared.hpp"
#include "agent/program/RobotProgram.hpp"
#include "sim/programs/ProgramDriver.hpp"

namespace simswift::programs {

class BuiltinProgram : public ProgramDriver {
 public:
  std::string error() const override { return program_->error(); }
  void join() override { program_->join(); }
  bool findBallView(sim::views::FindBallViewData& out) const override;
  bool belief(Belief& out) const override;
  agent::program::RobotProgram& program() { return *program_; }

 protected:
  // Connects `config`'s program to the slot's host and starts it (its
  // threads, or its inline steps, wait for the first tick).
  BuiltinProgram(RobotSlot slot, agent::program::ProgramConfig config, agent::program::Threading threading);
  std::unique_ptr<agent::program::RobotProgram> program_;
};

class ThreadedProgram final : public BuiltinProgram {
 public:
  ThreadedProgram(RobotSlot slot, agent::program::ProgramConfig config);
};

class InlineProgram : public BuiltinProgram {
 public:
  InlineProgram(RobotSlot slot, agent::program::ProgramConfig config);
  // The step for the tick or frame just posted, here; its answer is then
  // waiting. A step that throws ends the run at once (WatchdogError; a
  // thread would have gone silent).
  void posted(Step step, int64_t tick) override;
};

// The public API's controller (include/simswift/Simulation.hpp): sensors in,
// joint command out, each tick, on the simulator's thread. It goes through
// the same libagent block, in the same tick stage, as every other program.
using RawController = std::function<void(const common::libagent::SensorValues&, common::libagent::JointValues&)>;
// A controller that also sees libagent's `standing` and chest-button series
// and may send STIFFEN with its command (agent::program::LibagentIO: filled
// by the program before each Motion step, as an external program reads the block).
using LibagentExtras = agent::program::LibagentIO;
using RawLibagentController =
    std::function<void(const common::libagent::SensorValues&, common::libagent::JointValues&, LibagentExtras&)>;

class ApiController final : public InlineProgram {
 public:
  // `config`: the robot's program composed with motionStep(c) as its Motion step.
  ApiController(RobotSlot slot, agent::program::ProgramConfig config);
  static std::unique_ptr<agent::framework::MotionGenerator> motionStep(RawController c);
  // `io`: shared with the program (RobotProgram::setLibagentIO).
  static std::unique_ptr<agent::framework::MotionGenerator> motionStep(RawLibagentController c,
                                                                       std::shared_ptr<LibagentExtras> io);
};

}  // namespace simswift::programs
