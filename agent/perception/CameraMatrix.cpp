#include "agent/perception/CameraMatrix.hpp"

#include <algorithm>
#include <cmath>

namespace agent::perception {

using motion::Mat3;
using motion::Vec3;
namespace J = common::libagent::Joints;
namespace S = common::libagent::Sensors;

namespace {
motion::LegAngles legAngles(const float* a, bool left) {
  motion::LegAngles q;
  q.hip_yaw_pitch = a[J::LHipYawPitch];  // one motor drives both legs
  q.hip_roll = a[left ? J::LHipRoll : J::RHipRoll];
  q.hip_pitch = a[left ? J::LHipPitch : J::RHipPitch];
  q.knee = a[left ? J::LKneePitch : J::RKneePitch];
  q.ankle_pitch = a[left ? J::LAnklePitch : J::RAnklePitch];
  q.ankle_roll = a[left ? J::LAnkleRoll : J::RAnkleRoll];
  return q;
}
}  // namespace

CameraPose cameraPose(const common::libagent::SensorValues& sensors, common::nao::Camera camera) {
  namespace L = common::nao::links;
  const float* a = sensors.joints.angles;
  // The torso's tilt (roll about x, then pitch about y) from the inertial unit.
  const Mat3 tilt = Mat3::rotY(sensors.sensors[S::InertialSensor_AngleY]) *
                    Mat3::rotX(sensors.sensors[S::InertialSensor_AngleX]);
  // Soles in the torso frame, then levelled.
  const Vec3 left = tilt * (Vec3{0, L::kHipOffsetY, -L::kHipOffsetZ} +
                            motion::legForward(motion::Leg::Left, legAngles(a, true)).position);
  const Vec3 right = tilt * (Vec3{0, -L::kHipOffsetY, -L::kHipOffsetZ} +
                             motion::legForward(motion::Leg::Right, legAngles(a, false)).position);
  // The ground is under the lower sole (the support foot).
  const Vec3 origin{0.5 * (left.x + right.x), 0.5 * (left.y + right.y), std::min(left.z, right.z)};
  // Torso -> neck -> head (HeadYaw about z, HeadPitch about y) -> camera.
  const common::nao::CameraMount& m = common::nao::cameraMount(camera);
  const Mat3 head = Mat3::rotZ(a[J::HeadYaw]) * Mat3::rotY(a[J::HeadPitch]);
  const Vec3 in_torso = Vec3{0, 0, L::kNeckOffsetZ} + head * Vec3{m.x, m.y, m.z};
  CameraPose p;
  p.rotation = tilt * head * Mat3::rotY(m.pitch_down);
  p.position = tilt * in_torso - origin;
  return p;
}

bool viewAngles(const CameraPose& cam, double x, double y, double* horizontal, double* vertical) {
  const Vec3 d = cam.rotation.transposed() * (Vec3{x, y, 0} - cam.position);
  if (d.x <= 1.0) return false;
  *horizontal = std::atan2(d.y, d.x);
  *vertical = std::atan2(d.z, d.x);
  return true;
}

bool inFieldOfView(const CameraPose& cam, double x, double y, const common::nao::CameraLens& lens) {
  const Vec3 d = cam.rotation.transposed() * (Vec3{x, y, 0} - cam.position);
  if (d.x <= 1.0) return false;
  // Pinhole: the image plane coordinates are d.y / d.x and d.z / d.x.
  return std::fabs(d.y / d.x) <= std::tan(lens.horizontal_fov / 2) &&
         std::fabs(d.z / d.x) <= std::tan(lens.vertical_fov / 2);
}

}  // namespace agent::perception
