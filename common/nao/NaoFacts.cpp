#include "common/nao/NaoFacts.hpp"

namespace common::nao {

namespace {
// Degrees as published (float: the command type).
constexpr float kDegF = static_cast<float>(kDeg);
// Speeds by motor type (rad/s), Aldebaran's NAO V5 (H25) documentation.
constexpr float kFast = 8.268f, kMid = 7.194f, kLeg = 6.402f, kHip = 4.162f;
}  // namespace

const std::array<JointLimit, libagent::kNumJoints>& jointLimits() {
  namespace J = libagent::Joints;
  static const std::array<JointLimit, libagent::kNumJoints> table = [] {
    std::array<JointLimit, libagent::kNumJoints> t{};
    t[J::HeadYaw] = {-119.5f * kDegF, 119.5f * kDegF, kFast};
    t[J::HeadPitch] = {-38.5f * kDegF, 29.5f * kDegF, kMid};
    t[J::LShoulderPitch] = {-119.5f * kDegF, 119.5f * kDegF, kFast};
    t[J::LShoulderRoll] = {-18.0f * kDegF, 76.0f * kDegF, kMid};
    t[J::LElbowYaw] = {-119.5f * kDegF, 119.5f * kDegF, kFast};
    t[J::LElbowRoll] = {-88.5f * kDegF, -2.0f * kDegF, kMid};
    t[J::LWristYaw] = {-104.5f * kDegF, 104.5f * kDegF, 24.62f};
    t[J::LHand] = {0.0f, 1.0f, 8.33f};
    t[J::LHipYawPitch] = {-65.62f * kDegF, 42.44f * kDegF, kHip};
    t[J::LHipRoll] = {-21.74f * kDegF, 45.29f * kDegF, kHip};
    t[J::LHipPitch] = {-88.0f * kDegF, 27.73f * kDegF, kLeg};
    t[J::LKneePitch] = {-5.29f * kDegF, 121.04f * kDegF, kLeg};
    t[J::LAnklePitch] = {-68.15f * kDegF, 52.86f * kDegF, kLeg};
    t[J::LAnkleRoll] = {-22.79f * kDegF, 44.06f * kDegF, kHip};
    // Right side: pitch limits equal, roll limits mirrored.
    t[J::RHipRoll] = {-45.29f * kDegF, 21.74f * kDegF, kHip};
    t[J::RHipPitch] = t[J::LHipPitch];
    t[J::RKneePitch] = t[J::LKneePitch];
    t[J::RAnklePitch] = t[J::LAnklePitch];
    t[J::RAnkleRoll] = {-44.06f * kDegF, 22.79f * kDegF, kHip};
    t[J::RShoulderPitch] = t[J::LShoulderPitch];
    t[J::RShoulderRoll] = {-76.0f * kDegF, 18.0f * kDegF, kMid};
    t[J::RElbowYaw] = t[J::LElbowYaw];
    t[J::RElbowRoll] = {2.0f * kDegF, 88.5f * kDegF, kMid};
    t[J::RWristYaw] = t[J::LWristYaw];
    t[J::RHand] = t[J::LHand];
    return t;
  }();
  return table;
}

}  // namespace common::nao
