#include "agent/motion/Generators.hpp"

#include <algorithm>
#include <cmath>

#include "common/libagent/Inertial.hpp"
#include "common/nao/NaoFacts.hpp"
#include "agent/motion/JointLimits.hpp"
#include "agent/motion/Kinematics.hpp"
#include "agent/motion/Walk2014Generator.hpp"

namespace agent::motion {

namespace J = common::libagent::Joints;
namespace S = common::libagent::Sensors;

namespace {

using common::nao::kPi;  // common/nao/NaoFacts.hpp: one definition, also in a unity build

double ease(double f) {
  f = std::max(0.0, std::min(1.0, f));
  return 0.5 - 0.5 * std::cos(kPi * f);
}

void setArms(JointArray& a, float pitch, float roll, float elbow_yaw, float elbow_roll) {
  a[J::LShoulderPitch] = pitch;
  a[J::RShoulderPitch] = pitch;
  a[J::LShoulderRoll] = roll;
  a[J::RShoulderRoll] = -roll;
  a[J::LElbowYaw] = elbow_yaw;
  a[J::RElbowYaw] = -elbow_yaw;
  a[J::LElbowRoll] = elbow_roll;
  a[J::RElbowRoll] = -elbow_roll;
}

void setLegs(JointArray& a, float hyp, float roll, float hip, float knee, float ankle, float ankle_roll = 0) {
  a[J::LHipYawPitch] = hyp;
  a[J::LHipRoll] = roll;
  a[J::RHipRoll] = -roll;
  a[J::LHipPitch] = a[J::RHipPitch] = hip;
  a[J::LKneePitch] = a[J::RKneePitch] = knee;
  a[J::LAnklePitch] = a[J::RAnklePitch] = ankle;
  a[J::LAnkleRoll] = ankle_roll;
  a[J::RAnkleRoll] = -ankle_roll;
}

void writeLegs(const std::array<LegAngles, 2>& q, common::libagent::JointValues& out) {
  out.angles[J::LHipYawPitch] = static_cast<float>(q[0].hip_yaw_pitch);
  out.angles[J::LHipRoll] = static_cast<float>(q[0].hip_roll);
  out.angles[J::LHipPitch] = static_cast<float>(q[0].hip_pitch);
  out.angles[J::LKneePitch] = static_cast<float>(q[0].knee);
  out.angles[J::LAnklePitch] = static_cast<float>(q[0].ankle_pitch);
  out.angles[J::LAnkleRoll] = static_cast<float>(q[0].ankle_roll);
  out.angles[J::RHipRoll] = static_cast<float>(q[1].hip_roll);
  out.angles[J::RHipPitch] = static_cast<float>(q[1].hip_pitch);
  out.angles[J::RKneePitch] = static_cast<float>(q[1].knee);
  out.angles[J::RAnklePitch] = static_cast<float>(q[1].ankle_pitch);
  out.angles[J::RAnkleRoll] = static_cast<float>(q[1].ankle_roll);
}

}  // namespace

JointArray walkStandAngles(const WalkConfig& cfg) {
  Walk2014Generator walk(cfg);
  common::libagent::SensorValues s{};
  common::libagent::JointValues out{};
  walk.tick(s, kMotionTick, out);
  JointArray a{};
  for (int i = 0; i < common::libagent::kNumJoints; ++i) a[i] = out.angles[i];
  a[J::HeadYaw] = a[J::HeadPitch] = 0;
  return a;
}

JointArray crouchAngles() {
  common::libagent::JointValues out{};
  writeLegs(legsInverse(footPose(-10, 0, -160, 0), footPose(-10, 0, -160, 0)), out);
  JointArray a{};
  for (int i = 0; i < common::libagent::kNumJoints; ++i) a[i] = out.angles[i];
  setArms(a, 1.5f, 0.15f, -1.2f, -0.4f);
  return a;
}

// ------------------------------------------------------------------ head

void headPitchRange(float yaw, float* lower, float* upper) {
  // Approximation of the NAO's yaw-dependent pitch table: the full range
  // (-38.5..29.5 deg) up to |yaw| 0.8 rad, tightening linearly to
  // (-29.5..18 deg) at the yaw limit (2.086 rad).
  const auto& lim = jointLimits()[J::HeadPitch];
  const float a = std::fabs(yaw);
  const float k = a <= 0.8f ? 0.0f : std::min(1.0f, (a - 0.8f) / (2.086f - 0.8f));
  const float deg = 3.14159265f / 180.0f;
  *lower = lim.lower + k * (-29.5f * deg - lim.lower);
  *upper = lim.upper + k * (18.0f * deg - lim.upper);
}

void HeadGenerator::tick(const blackboard::HeadCommand& cmd, int64_t sequence,
                         const common::libagent::SensorValues& sensors, double dt, common::libagent::JointValues& out) {
  const float yaw_now = sensors.joints.angles[J::HeadYaw];
  const float pitch_now = sensors.joints.angles[J::HeadPitch];
  if (!primed_) {
    yaw_ = target_yaw_ = std::isfinite(yaw_now) ? yaw_now : 0.0f;
    pitch_ = target_pitch_ = std::isfinite(pitch_now) ? pitch_now : 0.0f;
    primed_ = true;
  }
  if (cmd.relative) {
    if (sequence != last_sequence_) {
      target_yaw_ = yaw_now + cmd.yaw;
      target_pitch_ = pitch_now + cmd.pitch;
    }
  } else {
    target_yaw_ = cmd.yaw;
    target_pitch_ = cmd.pitch;
  }
  last_sequence_ = sequence;
  if (!std::isfinite(target_yaw_)) target_yaw_ = yaw_;
  if (!std::isfinite(target_pitch_)) target_pitch_ = pitch_;
  const auto& lim = jointLimits();
  target_yaw_ = std::min(lim[J::HeadYaw].upper, std::max(lim[J::HeadYaw].lower, target_yaw_));
  float lo, hi;
  headPitchRange(target_yaw_, &lo, &hi);
  target_pitch_ = std::min(hi, std::max(lo, target_pitch_));

  const float yaw_speed = std::min(std::fabs(cmd.yaw_speed), lim[J::HeadYaw].max_velocity);
  const float pitch_speed = std::min(std::fabs(cmd.pitch_speed), lim[J::HeadPitch].max_velocity);
  const float dy = static_cast<float>(yaw_speed * dt), dp = static_cast<float>(pitch_speed * dt);
  yaw_ += std::max(-dy, std::min(dy, target_yaw_ - yaw_));
  pitch_ += std::max(-dp, std::min(dp, target_pitch_ - pitch_));
  out.angles[J::HeadYaw] = yaw_;
  out.angles[J::HeadPitch] = pitch_;
  out.stiffnesses[J::HeadYaw] = out.stiffnesses[J::HeadPitch] = 0.8f;
}

// ------------------------------------------------------------------ keyframes

void KeyframeGenerator::start(const std::vector<Keyframe>& frames, const JointArray& from) {
  frames_ = frames;
  from_ = from;
  frame_ = 0;
  t_ = 0;
  elapsed_ = 0;
}

void KeyframeGenerator::tick(double dt, common::libagent::JointValues& out, bool with_head) {
  if (frames_.empty()) return;
  const int first = with_head ? 0 : J::LShoulderPitch;
  if (done()) {
    const Keyframe& last = frames_.back();
    for (int i = first; i < common::libagent::kNumJoints; ++i) {
      out.angles[i] = last.angles[i];
      out.stiffnesses[i] = last.stiffness;
    }
    return;
  }
  t_ += dt;
  elapsed_ += dt;
  const Keyframe& k = frames_[frame_];
  const JointArray& a = frame_ == 0 ? from_ : frames_[frame_ - 1].angles;
  const double f = k.duration > 0 ? ease(t_ / k.duration) : 1.0;
  for (int i = first; i < common::libagent::kNumJoints; ++i) {
    out.angles[i] = static_cast<float>(a[i] + (k.angles[i] - a[i]) * f);
    out.stiffnesses[i] = k.stiffness;
  }
  if (t_ >= k.duration) {
    ++frame_;
    t_ = 0;
  }
}

// The get-ups are written in joint space. Signs: HipPitch < 0 folds the
// thigh forward, ShoulderPitch 0 points the arms along the torso's x,
// pi/2 down along the body, > pi/2 behind it.
std::vector<Keyframe> getupFrontFrames(const WalkConfig& cfg) {
  // Tuned in simswift for the NAO's motors (torque falling linearly with
  // speed, gear efficiency 0.8) by scripts/tune-getup-front.py, an
  // evolution strategy over the frames after the arms are overhead, scored
  // on pushed-over trials with noise seeds 500-505 (the test uses 100-109).
  // The previous sequence swept the arms from overhead down under the
  // shoulders while the chest lay on them: a 2.3 N*m shoulder cannot lift the
  // chest on a 0.2 m lever, so it stalled. This one tucks the legs first,
  // then pikes (hips flexed, knees straight, legs spread by HipYawPitch) so
  // the weight rocks back onto the feet and the arms only steady it; the
  // strong leg motors do the lifting.
  std::vector<Keyframe> f;
  JointArray a{};
  // Face down: arms out sideways along the ground (free to move there).
  setArms(a, 1.2f, 1.3f, 0.0f, -0.05f);
  setLegs(a, 0, 0, 0, 0, 0);
  f.push_back({0.3, a, 1.0f});
  // Turn the arms about their own axis to point overhead.
  setArms(a, -1.357f, 1.3f, 0.0f, -0.05f);
  f.push_back({0.3, a, 1.0f});
  // Arms in beside the head, elbows turned; legs still straight.
  setArms(a, -1.076f, 0.219f, -0.990f, -0.657f);
  setLegs(a, 0.282f, 0.227f, -0.334f, -0.053f, 0.030f, -0.126f);
  f.push_back({0.2, a, 1.0f});
  // Quick tuck: knees under the hips, HipYawPitch opened; arms stay forward.
  setArms(a, -1.5f, 0.188f, -1.277f, -0.04f);
  setLegs(a, -0.642f, 0.519f, -1.502f, 1.894f, -0.213f, 0.278f);
  f.push_back({0.2, a, 1.0f});
  // Pike: knees straight with the hips fully flexed and the legs spread, the
  // arms pushing back: the weight rocks back over the feet.
  setArms(a, 0.390f, 0.649f, 1.160f, -0.417f);
  setLegs(a, -0.762f, 0.521f, -1.53f, -0.032f, -0.232f, -0.105f);
  f.push_back({0.591, a, 1.0f});
  // Sink into a wide squat, arms forward for balance.
  setArms(a, 0.868f, 0.092f, -1.28f, -0.04f);
  setLegs(a, -0.552f, 0.561f, -1.103f, 1.434f, -0.283f, 0.283f);
  f.push_back({0.81, a, 1.0f});
  // Crouch, then stand.
  f.push_back({0.357, crouchAngles(), 1.0f});
  f.push_back({0.302, walkStandAngles(cfg), 1.0f});
  return f;
}

namespace {

// Asymmetric poses for the back get-up's roll (rad). Every value is the
// joint's own angle as sent: right-side rolls and yaws are not mirrored.
struct ArmPose {
  float shoulder_pitch, shoulder_roll, elbow_yaw, elbow_roll;
};
struct LegPose {
  float hip_roll, hip_pitch, knee, ankle_pitch, ankle_roll;
};

JointArray wholeBody(ArmPose l, ArmPose r, float hip_yaw_pitch, LegPose ll, LegPose rl) {
  JointArray a{};
  a[J::LShoulderPitch] = l.shoulder_pitch;
  a[J::LShoulderRoll] = l.shoulder_roll;
  a[J::LElbowYaw] = l.elbow_yaw;
  a[J::LElbowRoll] = l.elbow_roll;
  a[J::RShoulderPitch] = r.shoulder_pitch;
  a[J::RShoulderRoll] = r.shoulder_roll;
  a[J::RElbowYaw] = r.elbow_yaw;
  a[J::RElbowRoll] = r.elbow_roll;
  a[J::LHipYawPitch] = hip_yaw_pitch;
  a[J::LHipRoll] = ll.hip_roll;
  a[J::LHipPitch] = ll.hip_pitch;
  a[J::LKneePitch] = ll.knee;
  a[J::LAnklePitch] = ll.ankle_pitch;
  a[J::LAnkleRoll] = ll.ankle_roll;
  a[J::RHipRoll] = rl.hip_roll;
  a[J::RHipPitch] = rl.hip_pitch;
  a[J::RKneePitch] = rl.knee;
  a[J::RAnklePitch] = rl.ankle_pitch;
  a[J::RAnkleRoll] = rl.ankle_roll;
  return a;
}

}  // namespace

std::vector<Keyframe> getupBackFrames(const WalkConfig& cfg) {
  // Lying on the back the NAO cannot sit up: the shoulders (2.3 N*m) cannot
  // prop the torso, and bending the knees lets the legs rise instead of the
  // torso. So it rolls over its left side onto the front (about 1.5 s) and
  // then runs the front get-up. The three roll poses were found in simswift
  // by scripts/tune-getup-roll.py (an evolution strategy scored on standing
  // up after the whole sequence, tuned on other noise seeds than the test's):
  // 50 / 50 pushed-over trials stand on the first attempt, ~8 s after the push.
  std::vector<Keyframe> f;
  JointArray a{};
  // V-sit: hips flexed with straight legs lifts the torso to ~45 deg,
  // balanced on the seat against the legs; arms reach forward.
  setArms(a, 0.75f, 0.2f, 0.0f, -0.05f);
  setLegs(a, 0, 0, -1.5f, 0, 0);
  f.push_back({0.5, a, 1.0f});
  // Wind up: the left thigh stays raised, knee half bent; the right hip
  // extends with the knee folded; both arms out to the sides.
  f.push_back({0.55,
               wholeBody({0.629f, 0.861f, -0.011f, -0.596f}, {0.181f, -0.456f, -0.613f, 1.336f}, 0.74f,
                         {-0.135f, -1.129f, 0.62f, -1.18f, 0.76f}, {0.078f, 0.48f, 1.831f, 0.213f, -0.725f}),
               1.0f});
  // Whip (0.2 s): both arms swing overhead (the left one in across the
  // body), both hips extend and the right leg straightens: the body turns
  // over its left side.
  f.push_back({0.2,
               wholeBody({-1.538f, -0.31f, -1.29f, -0.646f}, {-1.591f, -1.037f, -0.657f, 1.34f}, -0.374f,
                         {-0.184f, 0.329f, 0.548f, -0.018f, -0.236f}, {0.37f, 0.48f, -0.09f, 0.533f, -0.503f}),
               1.0f});
  // Land face down: left arm back along the body, right arm out to the
  // side, both knees drawn in; the front get-up starts from here.
  f.push_back({0.85,
               wholeBody({1.741f, -0.31f, 0.373f, -0.701f}, {0.326f, -1.32f, 1.469f, 0.911f}, 0.74f,
                         {0.518f, -1.013f, 1.66f, -1.18f, -0.173f}, {-0.236f, -0.702f, 1.132f, 0.783f, -0.306f}),
               1.0f});
  // Face down now: the front get-up, unchanged (its crouch and stand are the
  // last two frames, where ActionMotion aborts into a safe fall if tipping).
  const std::vector<Keyframe> front = getupFrontFrames(cfg);
  f.insert(f.end(), front.begin(), front.end());
  return f;
}

// ------------------------------------------------------------------ kick

void KickGenerator::start(blackboard::Foot foot, double power, double direction) {
  foot_ = foot;
  power_ = std::isfinite(power) ? std::max(0.0, std::min(1.0, power)) : 1.0;
  direction_ = std::isfinite(direction) ? std::max(-0.8, std::min(0.8, direction)) : 0.0;
  started_ = true;
  phase_ = 0;
  t_ = 0;
  from_ = now_ = Target{0, 0, 0, 0, walk_.stand_hip_height};
}

// Targets per phase, for the kicking foot (x, y, z) and the hip shift over
// the support foot (mm), with the hip height (mm).
KickGenerator::Target KickGenerator::phaseTarget(int phase) const {
  const double back = -cfg_.wind_back * (0.4 + 0.6 * power_);
  const double side = std::max(-cfg_.max_side, std::min(cfg_.max_side, cfg_.reach * std::sin(direction_)));
  switch (phase) {
    case 0: return {0, 0, 0, cfg_.shift, cfg_.height};                      // shift over support
    case 1: return {0, 0, cfg_.lift, cfg_.shift, cfg_.height};              // lift
    case 2: return {back, 0, cfg_.lift, cfg_.shift, cfg_.height};           // wind back
    case 3: return {cfg_.reach * std::cos(direction_), side, cfg_.lift * 0.8, cfg_.shift, cfg_.height};  // strike
    case 4: return {cfg_.reach * std::cos(direction_), side, cfg_.lift * 0.8, cfg_.shift, cfg_.height};  // hold
    case 5: return {0, 0, cfg_.lift, cfg_.shift, cfg_.height};              // retract
    case 6: return {0, 0, 0, cfg_.shift, cfg_.height};                      // put down
    default: return {0, 0, 0, 0, walk_.stand_hip_height};                   // back to stand
  }
}

double KickGenerator::phaseDuration(int phase) const {
  switch (phase) {
    case 0: return 0.7;
    case 1: return 0.3;
    case 2: return 0.3;
    case 3: return cfg_.strike_time_fast + (cfg_.strike_time_slow - cfg_.strike_time_fast) * (1 - power_);
    case 4: return 0.15;
    case 5: return 0.4;
    case 6: return 0.3;
    default: return 0.6;
  }
}

void KickGenerator::tick(const common::libagent::SensorValues& sensors, double dt, common::libagent::JointValues& out) {
  // Roll and pitch rates, rad/s, right-handed (common/libagent/Inertial.hpp).
  const common::libagent::inertial::BodyRates w = common::libagent::inertial::bodyRates(sensors.sensors);
  gyro_x_ = 0.8 * gyro_x_ + 0.2 * w.x;
  gyro_y_ = 0.8 * gyro_y_ + 0.2 * w.y;
  if (started_ && !done()) {
    t_ += dt;
    const double d = phaseDuration(phase_);
    // The strike goes straight through (linear) to keep the foot fast at
    // contact; everything else eases.
    const double f = phase_ == 3 ? std::min(1.0, t_ / d) : ease(t_ / d);
    const Target to = phaseTarget(phase_);
    now_.x = from_.x + (to.x - from_.x) * f;
    now_.y = from_.y + (to.y - from_.y) * f;
    now_.z = from_.z + (to.z - from_.z) * f;
    now_.shift = from_.shift + (to.shift - from_.shift) * f;
    now_.height = from_.height + (to.height - from_.height) * f;
    if (t_ >= d) {
      from_ = to;
      ++phase_;
      t_ = 0;
    }
  }
  // Kicking right: the hips move left over the left foot, so both feet move
  // right (-y) in the hip frames. Mirror for a left kick.
  const bool kick_right = foot_ == blackboard::Foot::RIGHT;
  const double sgn = kick_right ? -1.0 : 1.0;
  const double shift_y = sgn * now_.shift;
  // now_.y aims the strike sideways in the robot frame (+ = left).
  const FootPose support = footPose(0, shift_y, -now_.height, 0);
  // With the hips far over the support foot, a level kicking sole would need
  // more AnkleRoll than the joint has (lifted, up to ~0.5 rad against a
  // 0.398 rad limit). Tilt the kicking sole by the excess instead, so every
  // target is one the leg reaches and no motor is driven into its stop.
  const auto& lim = jointLimits()[kick_right ? J::RAnkleRoll : J::LAnkleRoll];
  const double lo = lim.lower + cfg_.ankle_roll_margin, hi = lim.upper - cfg_.ankle_roll_margin;
  double sole_roll = 0;  // rad, the kicking sole's roll in the hip frame
  std::array<LegAngles, 2> q{};
  for (int pass = 0; pass < 3; ++pass) {
    const FootPose kicking = footPose(now_.x, shift_y + now_.y, -now_.height + now_.z, 0, sole_roll);
    q = kick_right ? legsInverse(support, kicking) : legsInverse(kicking, support);
    const double roll = q[kick_right ? 1 : 0].ankle_roll;
    const double excess = roll - std::max(lo, std::min(hi, roll));
    if (excess == 0) break;
    sole_roll -= excess;  // the sole rolls with the ankle, the hip roll barely changes
  }
  writeLegs(q, out);
  // Balance on the support ankle (same feedback as the walk).
  const int sp = kick_right ? J::LAnklePitch : J::RAnklePitch;
  const int sr = kick_right ? J::LAnkleRoll : J::RAnkleRoll;
  out.angles[sp] += static_cast<float>(walk_.gyro_pitch_gain * gyro_y_);
  out.angles[sr] += static_cast<float>(walk_.gyro_roll_gain * gyro_x_);
  // Arms out a little for balance, swinging against the leg as a person's
  // do: the kicking side's arm goes back (ShoulderPitch up) and the other
  // forward while the foot goes forward. The leg's swing puts angular
  // momentum about the vertical into the body that the stance foot's friction
  // must take; the arms' opposite swing takes part of it, so the stance foot
  // and the aim turn less.
  // Kept off the ShoulderPitch stops (a motor held at a stop only heats).
  const double swing = cfg_.arm_swing * now_.x;
  const auto& sh = jointLimits()[J::LShoulderPitch];  // both shoulders share the range
  const auto arm = [&](double a) { return static_cast<float>(std::max(sh.lower + 0.05, std::min(sh.upper - 0.05, a))); };
  out.angles[J::LShoulderPitch] = arm(1.5 + (kick_right ? -swing : swing));
  out.angles[J::RShoulderPitch] = arm(1.5 + (kick_right ? swing : -swing));
  out.angles[J::LShoulderRoll] = 0.25f;
  out.angles[J::RShoulderRoll] = -0.25f;
  out.angles[J::LElbowYaw] = -1.2f;
  out.angles[J::RElbowYaw] = 1.2f;
  out.angles[J::LElbowRoll] = -0.4f;
  out.angles[J::RElbowRoll] = 0.4f;
  out.angles[J::LWristYaw] = out.angles[J::RWristYaw] = 0;
  out.angles[J::LHand] = out.angles[J::RHand] = 0;
  for (int i = J::LShoulderPitch; i < common::libagent::kNumJoints; ++i)
    out.stiffnesses[i] = static_cast<float>(cfg_.stiffness);
}

// ------------------------------------------------------------------ limp

void limpJoints(const common::libagent::SensorValues& sensors, float stiffness, common::libagent::JointValues& out) {
  for (int i = 0; i < common::libagent::kNumJoints; ++i) {
    const float a = sensors.joints.angles[i];
    if (std::isfinite(a)) out.angles[i] = a;
    out.stiffnesses[i] = stiffness;
  }
}

}  // namespace agent::motion
