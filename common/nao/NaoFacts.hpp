// NAO V5 (H25) hardware facts for the robot code: link lengths, camera
// mountings and fields of view, FSR positions, joint limits and speeds.
// The one home of these numbers: agent/ uses them for kinematics, the walk
// and the camera matrix; sim/ includes this header for the same facts (the
// simulator may include agent/ headers, never the reverse). The figures are
// the published Aldebaran ones restated in Aldebaran's NAO V5 (H25) documentation;
// tests/nao_model/test_nao_facts.cpp holds them against models/nao_v5.urdf.
//
// Units: mm, rad, rad/s. Frames: x forward, y left, z up (NAO convention).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "common/libagent/AgentShared.hpp"

namespace common::nao {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// ---------------------------------------------------------------- links (mm)
namespace links {
constexpr double kNeckOffsetZ = 126.5;    // torso origin -> HeadYaw axis
constexpr double kHipOffsetY = 50.0;      // torso origin -> hip joint, sideways
constexpr double kHipOffsetZ = 85.0;      // torso origin -> hip joint, down
constexpr double kThighLength = 100.0;    // hip -> knee
constexpr double kTibiaLength = 102.9;    // knee -> ankle
constexpr double kFootHeight = 45.19;     // ankle -> sole
constexpr double kShoulderOffsetY = 98.0;
constexpr double kShoulderOffsetZ = 100.0;
constexpr double kUpperArmLength = 105.0;
constexpr double kElbowOffsetY = 15.0;
constexpr double kLowerArmLength = 55.95;
}  // namespace links

// Seen from above, standing: the circle round the torso's vertical axis that
// holds the body and the arms hanging at its sides (the shoulder joints are
// kShoulderOffsetY = 98 mm from it). The simulator spaces robots at placement
// and draws them with it; the robot code's avoidance radius defaults to it
// (BehaviourConfig::robot_radius).
constexpr double kFootprintRadius = 150.0;  // mm

// ---------------------------------------------------------------- cameras
enum class Camera : int { Top = 0, Bottom = 1 };

// Fixed mounting in the frame of the link HeadPitch moves ("head frame").
struct CameraMount {
  double x, y, z;     // mm, camera centre in the head frame
  double pitch_down;  // rad, optical axis tipped down from the head's x axis
};
constexpr CameraMount kTopCamera{58.71, 0.0, 63.64, 1.2 * kDeg};
constexpr CameraMount kBottomCamera{50.71, 0.0, 17.74, 39.7 * kDeg};
constexpr const CameraMount& cameraMount(Camera c) { return c == Camera::Top ? kTopCamera : kBottomCamera; }

// The V6 mounts both cameras where the V5 does: Aldebaran's NAOH25V60.urdf
// (NAOqi 2.8) gives the same offsets and tilts (cited and used by rUNSWift's
// 2022 release, robot/perception/kinematics/Kinematics.cpp).

// Both cameras of a robot: the same lens. The V5's MT9M114: 60.9 x 47.6 deg
// (Aldebaran's NAO V5 (H25) documentation); the V6's OV5640: 56.3 x 43.7 deg
// (Aldebaran's NAOqi 2.8 "NAO V6 video camera" specifications, as rUNSWift's
// 2022 release reads them: robot/perception/vision/VisionDefinitions.hpp).
struct CameraLens {
  double horizontal_fov;  // rad
  double vertical_fov;    // rad
};
constexpr CameraLens kV5CameraLens{60.9 * kDeg, 47.6 * kDeg};
constexpr CameraLens kV6CameraLens{56.3 * kDeg, 43.7 * kDeg};
constexpr int kCameraFramesPerSecond = 30;            // both cameras; Perception's rate
constexpr double kCameraRateHz = kCameraFramesPerSecond;  // Hz

// ---------------------------------------------------------------- timing
// The DCM's cycle: sensors in, joint commands out, and the Motion thread's
// tick (rUNSWift 2017 release, robot/libagent). The one home of the 10 ms tick for robot code
// and simulator alike.
// The tick belongs to the body's interface: this is libagent's on the V5
// (a V6 over LoLA runs 12 ms; docs/architecture.md).
constexpr int64_t kMotionTickUs = 10000;                        // us (100 Hz)
constexpr double kMotionTickSeconds = kMotionTickUs * 1e-6;     // s
// Whole ticks in `seconds` s, rounded to the nearest (durations, time limits).
inline int64_t ticksIn(double seconds) { return std::llround(seconds / kMotionTickSeconds); }
// The same for a robot of another cycle (the V6's LoLA: 12 ms), us per tick.
inline int64_t ticksIn(double seconds, int64_t tick_us) {
  return std::llround(seconds / (static_cast<double>(tick_us) * 1e-6));
}

// ---------------------------------------------------------------- FSRs
// Order as in libagent: FrontLeft, FrontRight, RearLeft, RearRight.
enum class Fsr : int { FrontLeft = 0, FrontRight = 1, RearLeft = 2, RearRight = 3 };
enum class Side : int { Left = 0, Right = 1 };

struct Point2 {
  double x, y;  // mm
};
// Left foot, in the left ankle frame (mm). Not an exact rectangle.
constexpr std::array<Point2, 4> kLeftFsr{{{70.25, 29.9}, {70.25, -23.1}, {-30.25, 29.9}, {-29.65, -19.1}}};

// A sensor's position in its own foot's ankle frame (mm). The right foot is
// the mirror image: its front-left sensor mirrors the left foot's front-right.
constexpr Point2 fsrPosition(Side side, Fsr which) {
  const int i = static_cast<int>(which);
  if (side == Side::Left) return kLeftFsr[i];
  const int mirror = i ^ 1;  // FrontLeft <-> FrontRight, RearLeft <-> RearRight
  return {kLeftFsr[mirror].x, -kLeftFsr[mirror].y};
}

// ---------------------------------------------------------------- joints
struct JointLimit {
  float lower, upper;  // rad (Hand: 0..1 fraction open)
  float max_velocity;  // rad/s (Hand: fraction/s)
};
// Indexed by libagent::Joints::JointCode.
const std::array<JointLimit, libagent::kNumJoints>& jointLimits();

}  // namespace common::nao
