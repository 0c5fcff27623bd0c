#include "agent/motion/Kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace agent::motion {

using namespace NaoDims;

Mat3 Mat3::rotX(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r.m[1][1] = c; r.m[1][2] = -s;
  r.m[2][1] = s; r.m[2][2] = c;
  return r;
}
Mat3 Mat3::rotY(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r.m[0][0] = c; r.m[0][2] = s;
  r.m[2][0] = -s; r.m[2][2] = c;
  return r;
}
Mat3 Mat3::rotZ(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r.m[0][0] = c; r.m[0][1] = -s;
  r.m[1][0] = s; r.m[1][1] = c;
  return r;
}
Mat3 Mat3::transposed() const {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = m[j][i];
  return r;
}
Mat3 operator*(const Mat3& a, const Mat3& b) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += a.m[i][k] * b.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}
Vec3 operator*(const Mat3& a, Vec3 v) {
  return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
          a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
          a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
}

namespace {

constexpr double kQuarterPi = 0.78539816339744831;

// HipYawPitch as a rotation: about (0, 1, -1)/sqrt2 for the left leg, which
// is z turned by Rx(pi/4) and negated; about (0, 1, 1)/sqrt2 for the right.
Mat3 hipYawPitch(Leg leg, double q) {
  if (leg == Leg::Left) return Mat3::rotX(kQuarterPi) * Mat3::rotZ(-q) * Mat3::rotX(-kQuarterPi);
  return Mat3::rotX(-kQuarterPi) * Mat3::rotZ(q) * Mat3::rotX(kQuarterPi);
}

double clampUnit(double v) { return std::max(-1.0, std::min(1.0, v)); }

// Angle of an x-z vector from straight down, positive toward +x (rad).
double angleFromDown(double x, double z) { return std::atan2(x, -z); }

// Solves HipRoll..AnkleRoll for a fixed HipYawPitch: the sole position is
// met exactly (when reachable); the sole orientation as closely as five
// joints allow (its pitch and roll exactly when the yaw is consistent).
LegAngles solveGivenYawPitch(Leg leg, const FootPose& target, double q0, bool* reachable) {
  LegAngles q;
  q.hip_yaw_pitch = q0;
  const Mat3 m0t = hipYawPitch(leg, q0).transposed();
  const Mat3 r1 = m0t * target.rotation;  // foot axes after HipYawPitch
  const Vec3 ankle = m0t * target.position + r1 * Vec3{0, 0, kFootHeight};

  q.hip_roll = std::atan2(ankle.y, -ankle.z);
  const Vec3 in_plane = Mat3::rotX(-q.hip_roll) * ankle;  // y == 0 now

  const double max_len = kThighLength + kTibiaLength;
  const double min_len = std::fabs(kThighLength - kTibiaLength) + 1e-6;
  double d = std::sqrt(in_plane.x * in_plane.x + in_plane.z * in_plane.z);
  bool ok = true;
  if (d > max_len) { d = max_len; ok = false; }
  if (d < min_len) { d = min_len; ok = false; }
  if (reachable) *reachable = ok;

  const double cos_knee = (d * d - kThighLength * kThighLength - kTibiaLength * kTibiaLength) /
                          (2 * kThighLength * kTibiaLength);
  q.knee = std::acos(clampUnit(cos_knee));
  // Hip-to-ankle vector in the thigh frame at this knee angle.
  const double vx = -kTibiaLength * std::sin(q.knee);
  const double vz = -kThighLength - kTibiaLength * std::cos(q.knee);
  q.hip_pitch = angleFromDown(vx, vz) - angleFromDown(in_plane.x, in_plane.z);

  // Remaining rotation the ankle must supply: Ry(knee + ankle_pitch) Rx(ankle_roll).
  const Mat3 upper = Mat3::rotX(q.hip_roll) * Mat3::rotY(q.hip_pitch);
  const Mat3 rest = upper.transposed() * r1;
  q.ankle_roll = std::atan2(-rest.m[1][2], rest.m[1][1]);
  const double pitch_sum = std::atan2(-rest.m[2][0], rest.m[0][0]);
  // pitch_sum is knee + ankle_pitch, measured in the thigh frame.
  q.ankle_pitch = pitch_sum - q.knee;
  return q;
}

}  // namespace

FootPose legForward(Leg leg, const LegAngles& q) {
  const Mat3 r_hip = hipYawPitch(leg, q.hip_yaw_pitch) * Mat3::rotX(q.hip_roll) *
                     Mat3::rotY(q.hip_pitch);
  const Mat3 r_knee = r_hip * Mat3::rotY(q.knee);
  const Mat3 r_foot = r_knee * Mat3::rotY(q.ankle_pitch) * Mat3::rotX(q.ankle_roll);
  FootPose f;
  f.position = r_hip * Vec3{0, 0, -kThighLength} + r_knee * Vec3{0, 0, -kTibiaLength} +
               r_foot * Vec3{0, 0, -kFootHeight};
  f.rotation = r_foot;
  return f;
}

LegAngles legInverse(Leg leg, const FootPose& target, bool* reachable) {
  // The sole rotation is R = Y(q0) Rx(q1) Ry(q2 + q3 + q4) Rx(q5). The ankle
  // joints and knee follow from the hip seen from the foot; what is left is
  // the thigh's orientation, decomposed in the frame turned so the
  // HipYawPitch axis is z (there Y(q0) is a plain Rz).
  const Vec3 ankle = target.position + target.rotation * Vec3{0, 0, kFootHeight};
  // Ankle-to-hip direction in the foot frame gives the ankle roll and the
  // leg's in-plane geometry.
  const Vec3 h = target.rotation.transposed() * (Vec3{0, 0, 0} - ankle);
  const double ankle_roll = std::atan2(h.y, h.z);
  const double rho = std::sqrt(h.y * h.y + h.z * h.z);
  double d = std::sqrt(h.x * h.x + rho * rho);
  d = std::min(d, kThighLength + kTibiaLength);
  const double cos_knee = (d * d - kThighLength * kThighLength - kTibiaLength * kTibiaLength) /
                          (2 * kThighLength * kTibiaLength);
  const double knee = std::acos(clampUnit(cos_knee));
  const double beta = std::atan2(kThighLength * std::sin(knee), kThighLength * std::cos(knee) + kTibiaLength);
  // u = hip-to-ankle in the foot frame = -h; its in-plane angle.
  const double ankle_pitch = std::atan2(-h.x, rho) - beta;

  // Thigh frame orientation M = R Rx(-q5) Ry(-(q3 + q4)) = Y(q0) Rx(q1) Ry(q2).
  const Mat3 m = target.rotation * Mat3::rotX(-ankle_roll) * Mat3::rotY(-(knee + ankle_pitch));
  const double tilt = leg == Leg::Left ? -kQuarterPi : kQuarterPi;
  const Mat3 n = Mat3::rotX(tilt) * m;  // = Rz(+-q0) Rx(q1 -+ pi/4) Ry(q2)
  const double alpha = std::atan2(-n.m[0][1], n.m[1][1]);
  const double q0 = leg == Leg::Left ? -alpha : alpha;
  // The remaining five joints from the common solver (same answer, and it
  // handles out-of-reach targets consistently).
  return solveGivenYawPitch(leg, target, q0, reachable);
}

FootPose footPose(double x, double y, double z, double yaw, double roll, double pitch) {
  FootPose f;
  f.position = {x, y, z};
  f.rotation = Mat3::rotZ(yaw) * Mat3::rotY(pitch) * Mat3::rotX(roll);
  return f;
}

std::array<LegAngles, 2> legsInverse(const FootPose& left, const FootPose& right) {
  const LegAngles l = legInverse(Leg::Left, left);
  const LegAngles r = legInverse(Leg::Right, right);
  const double q0 = 0.5 * (l.hip_yaw_pitch + r.hip_yaw_pitch);
  // With a shared q0 a leg can't match its sole yaw exactly, so the sole
  // point sits FootHeight off the ankle along a slightly different axis;
  // two refinements aim the ankle using the orientation actually reached,
  // which keeps the sole position exact.
  std::array<LegAngles, 2> out;
  const FootPose* targets[2] = {&left, &right};
  for (int i = 0; i < 2; ++i) {
    const Leg leg = i == 0 ? Leg::Left : Leg::Right;
    FootPose aim = *targets[i];
    LegAngles q = solveGivenYawPitch(leg, aim, q0, nullptr);
    for (int it = 0; it < 3; ++it) {
      const FootPose got = legForward(leg, q);
      aim.position = aim.position + (targets[i]->position - got.position);
      q = solveGivenYawPitch(leg, aim, q0, nullptr);
    }
    out[i] = q;
  }
  return out;
}

}  // namespace agent::motion
