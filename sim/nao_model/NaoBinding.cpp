// NaoBinding: the NAO's libagent joints in a RobotModel (see NaoBinding.hpp).
#include "sim/nao_model/NaoBinding.hpp"

#include <string>

#include "sim/nao_model/RobotBody.hpp"

namespace simswift {

namespace la = common::libagent;

namespace {

[[noreturn]] void fail(const RobotModel& model, int line, const std::string& what) {
  throw ModelError(model.source(), line, what);
}

}  // namespace

NaoBinding::NaoBinding(const RobotModel& model) : model_(&model), joint_to_slot_(model.joints().size(), -1) {
  const auto& joints = model.joints();
  for (int i = 0; i < la::kNumJoints; ++i) {
    const int j = model.jointIndex(la::Joints::kNames[i]);
    if (j < 0)
      fail(model, model.robotLine(),
           std::string("missing joint '") + la::Joints::kNames[i] + "' (a libagent joint)");
    if (joints[j].mimic)
      fail(model, joints[j].mimic_line,
           std::string("joint '") + la::Joints::kNames[i] + "' is a libagent joint and cannot be a mimic");
    slot_to_joint_[i] = j;
    joint_to_slot_[j] = i;
  }
  // The NAO's two HipYawPitch joints share one motor: without the mimic the
  // right hip would hang free and the robot falls over when it walks.
  const int rhyp = model.jointIndex("RHipYawPitch");
  if (rhyp < 0) fail(model, model.robotLine(), "missing joint 'RHipYawPitch' (it mimics LHipYawPitch)");
  const JointSpec& r = joints[rhyp];
  if (!r.mimic || *r.mimic != "LHipYawPitch" || r.mimic_multiplier != 1.0)
    fail(model, r.mimic_line,
         "joint 'RHipYawPitch' needs <mimic joint=\"LHipYawPitch\" multiplier=\"1\"/> (the NAO drives both "
         "HipYawPitch joints with one motor)");
}

std::vector<double> NaoBinding::posture(const SlotArray& angles) const {
  const auto& joints = model_->joints();
  std::vector<double> q(joints.size(), 0.0);
  for (int i = 0; i < la::kNumJoints; ++i) q[slot_to_joint_[i]] = angles[i];
  for (size_t j = 0; j < joints.size(); ++j)
    if (joints[j].mimic) q[j] = joints[j].mimic_multiplier * q[model_->jointIndex(*joints[j].mimic)];
  return q;
}

void NaoBinding::command(RobotBody& body, const SlotArray& angles, const SlotArray& stiffnesses) const {
  for (int i = 0; i < la::kNumJoints; ++i) body.setTarget(slot_to_joint_[i], angles[i], stiffnesses[i]);
}

}  // namespace simswift
