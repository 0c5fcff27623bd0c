// The NAO's binding to libagent: which model joint each of libagent's 25
// joint slots drives (common/libagent/AgentShared.hpp, Joints::kNames), and
// the one motor the two HipYawPitch joints share. A RobotModel
// (RobotModel.hpp) is any URDF; it must pass this check before a robot
// program drives it through libagent (the runner checks it when it
// attaches the robots, simswift --check before a run).
//
// Units: rad. Slots in libagent order; joints in the model's order.
#pragma once

#include <array>
#include <vector>

#include "common/libagent/AgentShared.hpp"  // kNumJoints: the 25 libagent joints
#include "sim/nao_model/RobotModel.hpp"

namespace simswift {

class RobotBody;

class NaoBinding {
 public:
  using SlotArray = std::array<float, common::libagent::kNumJoints>;

  // Checks that `model` has every libagent joint (none of them a mimic) and
  // that RHipYawPitch mimics LHipYawPitch with multiplier 1. Throws
  // ModelError "source:line: ..." (the model's source and the line of its
  // <robot>, or of the offending joint). `model` must outlive the binding.
  explicit NaoBinding(const RobotModel& model);

  const RobotModel& model() const { return *model_; }
  // The model joint driven by libagent slot i (0..24).
  int joint(int slot) const { return slot_to_joint_[slot]; }
  // The libagent slot driving model joint j, -1 if none (RHipYawPitch).
  int slot(int joint) const { return joint_to_slot_[joint]; }

  // A posture in model joint order from 25 libagent-order angles (rad);
  // mimicking joints (RHipYawPitch) copy the joint they follow.
  std::vector<double> posture(const SlotArray& angles) const;
  // Latches a libagent command on `body` (built from this binding's model):
  // each slot's angle (rad) and stiffness to its joint's servo; the mimics
  // follow their leaders.
  void command(RobotBody& body, const SlotArray& angles, const SlotArray& stiffnesses) const;

 private:
  const RobotModel* model_;
  std::array<int, common::libagent::kNumJoints> slot_to_joint_{};
  std::vector<int> joint_to_slot_;
};

}  // namespace simswift
