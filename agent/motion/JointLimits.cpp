#include "agent/motion/JointLimits.hpp"

#include <algorithm>
#include <cmath>

namespace agent::motion {

namespace {
constexpr float kDeg = 3.14159265358979f / 180.0f;
// Speeds by motor type (rad/s), facts.md section 1.
constexpr float kFast = 8.268f, kMid = 7.194f, kLeg = 6.402f, kHip = 4.162f;
}  // namespace

const std::array<JointLimit, libagent::kNumJoints>& jointLimits() {
  namespace J = libagent::Joints;
  static const std::array<JointLimit, libagent::kNumJoints> table = [] {
    std::array<JointLimit, libagent::kNumJoints> t{};
    t[J::HeadYaw] = {-119.5f * kDeg, 119.5f * kDeg, kFast};
    t[J::HeadPitch] = {-38.5f * kDeg, 29.5f * kDeg, kMid};
    t[J::LShoulderPitch] = {-119.5f * kDeg, 119.5f * kDeg, kFast};
    t[J::LShoulderRoll] = {-18.0f * kDeg, 76.0f * kDeg, kMid};
    t[J::LElbowYaw] = {-119.5f * kDeg, 119.5f * kDeg, kFast};
    t[J::LElbowRoll] = {-88.5f * kDeg, -2.0f * kDeg, kMid};
    t[J::LWristYaw] = {-104.5f * kDeg, 104.5f * kDeg, 24.62f};
    t[J::LHand] = {0.0f, 1.0f, 8.33f};
    t[J::LHipYawPitch] = {-65.62f * kDeg, 42.44f * kDeg, kHip};
    t[J::LHipRoll] = {-21.74f * kDeg, 45.29f * kDeg, kHip};
    t[J::LHipPitch] = {-88.0f * kDeg, 27.73f * kDeg, kLeg};
    t[J::LKneePitch] = {-5.29f * kDeg, 121.04f * kDeg, kLeg};
    t[J::LAnklePitch] = {-68.15f * kDeg, 52.86f * kDeg, kLeg};
    t[J::LAnkleRoll] = {-22.79f * kDeg, 44.06f * kDeg, kHip};
    // Right side: pitch limits equal, roll limits mirrored.
    t[J::RHipRoll] = {-45.29f * kDeg, 21.74f * kDeg, kHip};
    t[J::RHipPitch] = t[J::LHipPitch];
    t[J::RKneePitch] = t[J::LKneePitch];
    t[J::RAnklePitch] = t[J::LAnklePitch];
    t[J::RAnkleRoll] = {-44.06f * kDeg, 22.79f * kDeg, kHip};
    t[J::RShoulderPitch] = t[J::LShoulderPitch];
    t[J::RShoulderRoll] = {-76.0f * kDeg, 18.0f * kDeg, kMid};
    t[J::RElbowYaw] = t[J::LElbowYaw];
    t[J::RElbowRoll] = {2.0f * kDeg, 88.5f * kDeg, kMid};
    t[J::RWristYaw] = t[J::LWristYaw];
    t[J::RHand] = t[J::LHand];
    return t;
  }();
  return table;
}

void Clipper::clip(libagent::JointValues& cmd, const libagent::JointValues& sensed) {
  const auto& lim = jointLimits();
  for (int i = 0; i < libagent::kNumJoints; ++i) {
    // 1e-5 rad inside the limits: a float at the limit may round past the
    // body side's double-precision limit.
    const float lo = lim[i].lower + 1e-5f, hi = lim[i].upper - 1e-5f;
    float a = cmd.angles[i];
    if (!std::isfinite(a)) a = primed_ ? last_[i] : sensed.angles[i];
    if (!std::isfinite(a)) a = 0.0f;
    a = std::min(hi, std::max(lo, a));
    if (!primed_) {
      // Start where the joint is (itself clamped into range).
      float s = sensed.angles[i];
      if (!std::isfinite(s)) s = 0.0f;
      last_[i] = std::min(hi, std::max(lo, s));
    }
    // A hair under the limit so float rounding never exceeds it.
    const float step = static_cast<float>(lim[i].max_velocity * kMotionTick) * 0.9999f;
    a = std::min(last_[i] + step, std::max(last_[i] - step, a));
    a = std::min(hi, std::max(lo, a));
    cmd.angles[i] = a;
    last_[i] = a;
    float s = cmd.stiffnesses[i];
    if (!std::isfinite(s)) s = 0.0f;
    cmd.stiffnesses[i] = s < 0.0f ? -1.0f : std::min(1.0f, s);
  }
  primed_ = true;
}

}  // namespace agent::motion
