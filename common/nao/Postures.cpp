#include "common/nao/Postures.hpp"

namespace common::nao {

namespace J = common::libagent::Joints;

namespace {
// Arms hanging beside the body: shoulders pitched down (rad), elbows a little
// bent, each side mirrored (roll and yaw change sign).
void setArms(JointArray& a) {
  a[J::LShoulderPitch] = 1.5f;
  a[J::LShoulderRoll] = 0.15f;
  a[J::LElbowYaw] = -1.2f;
  a[J::LElbowRoll] = -0.4f;
  a[J::RShoulderPitch] = 1.5f;
  a[J::RShoulderRoll] = -0.15f;
  a[J::RElbowYaw] = 1.2f;
  a[J::RElbowRoll] = 0.4f;
}
void setLegs(JointArray& a, float hip, float knee, float ankle) {
  a[J::LHipPitch] = hip;
  a[J::LKneePitch] = knee;
  a[J::LAnklePitch] = ankle;
  a[J::RHipPitch] = hip;
  a[J::RKneePitch] = knee;
  a[J::RAnklePitch] = ankle;
}
}  // namespace

JointArray postureAngles(Posture p) {
  JointArray a{};
  switch (p) {
    case Posture::Stand:
    case Posture::Limp:
      setArms(a);
      setLegs(a, -0.4f, 0.8f, -0.4f);
      break;
    case Posture::Crouch:
      setArms(a);
      setLegs(a, -0.8f, 1.6f, -0.8f);
      break;
    case Posture::Zero:
      break;
  }
  return a;
}

float postureStiffness(Posture p) { return p == Posture::Limp ? 0.0f : 1.0f; }

const char* postureName(Posture p) {
  switch (p) {
    case Posture::Stand: return "stand";
    case Posture::Crouch: return "crouch";
    case Posture::Limp: return "limp";
    case Posture::Zero: return "zero";
  }
  return "?";
}

std::optional<Posture> parsePosture(const std::string& name) {
  for (Posture p : {Posture::Stand, Posture::Crouch, Posture::Limp, Posture::Zero})
    if (name == postureName(p)) return p;
  return std::nullopt;
}

common::libagent::JointValues postureCommand(Posture p) {
  common::libagent::JointValues v{};
  const JointArray a = postureAngles(p);
  const float s = postureStiffness(p);
  for (int i = 0; i < common::libagent::kNumJoints; ++i) {
    v.angles[i] = a[i];
    v.stiffnesses[i] = s;
  }
  return v;
}

int jointIndex(const std::string& name) {
  for (int i = 0; i < common::libagent::kNumJoints; ++i)
    if (name == J::kNames[i]) return i;
  return -1;
}

const std::vector<std::string>& postureNames() {
  static const std::vector<std::string> names = {"stand", "crouch", "limp", "zero"};
  return names;
}

}  // namespace common::nao
