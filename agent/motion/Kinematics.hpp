// NAO V5 leg kinematics: closed-form inverse kinematics and the forward
// kinematics that checks it. Plain maths (no Eigen) so the robot code keeps
// to the standard library.
//
// Frames: the "hip frame" of a leg has its origin at that leg's hip joint
// centre (torso frame shifted by (0, +-HipOffsetY, -HipOffsetZ)) and the
// torso's axes (x forward, y left, z up). A foot pose is the pose of the sole
// point (FootHeight below the ankle joint) in that frame. Lengths mm, angles rad.
#pragma once

#include <array>

#include "common/nao/NaoFacts.hpp"

namespace agent::motion {

// Link lengths (mm): the NAO hardware facts (common/nao/NaoFacts.hpp).
namespace NaoDims = common::nao::links;

struct Vec3 {
  double x = 0, y = 0, z = 0;
};
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }

// Row-major 3x3 rotation.
struct Mat3 {
  double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  static Mat3 rotX(double a);
  static Mat3 rotY(double a);
  static Mat3 rotZ(double a);
  Mat3 transposed() const;
};
Mat3 operator*(const Mat3& a, const Mat3& b);
Vec3 operator*(const Mat3& a, Vec3 v);

enum class Leg { Left, Right };

// The six leg joints in chain order (rad): HipYawPitch, HipRoll, HipPitch,
// KneePitch, AnklePitch, AnkleRoll.
struct LegAngles {
  double hip_yaw_pitch = 0, hip_roll = 0, hip_pitch = 0;
  double knee = 0, ankle_pitch = 0, ankle_roll = 0;
};

struct FootPose {
  Vec3 position;  // mm, sole point in the hip frame
  Mat3 rotation;  // foot axes in the hip frame
};

// Forward kinematics of one leg: the sole pose in that leg's hip frame.
FootPose legForward(Leg leg, const LegAngles& q);

// Inverse kinematics of one leg (all six joints free). Targets out of reach
// are pulled in to the reachable length (the leg straightens) rather than
// producing NaN; `reachable` reports whether that happened.
LegAngles legInverse(Leg leg, const FootPose& target, bool* reachable = nullptr);

// Convenience for the walk: foot at (x, y, z) mm in the hip frame, yawed by
// `yaw` rad, sole rolled/pitched by `roll`/`pitch` rad (0 = parallel to the
// torso's x-y plane).
FootPose footPose(double x, double y, double z, double yaw, double roll = 0, double pitch = 0);

// Both legs at once: the NAO has one HipYawPitch motor for both legs, so the
// two legs' HipYawPitch values are averaged (they agree exactly when the feet
// are mirror images in yaw, which the walk keeps them). Returns the left and
// right angles with hip_yaw_pitch equal.
std::array<LegAngles, 2> legsInverse(const FootPose& left, const FootPose& right);

}  // namespace agent::motion
