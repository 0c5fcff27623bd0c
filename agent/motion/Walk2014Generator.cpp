#include "agent/motion/Walk2014Generator.hpp"

#include <algorithm>
#include <cmath>

#include "common/libagent/Inertial.hpp"
#include "common/nao/NaoFacts.hpp"
#include "agent/motion/Kinematics.hpp"

namespace agent::motion {

namespace J = common::libagent::Joints;
namespace S = common::libagent::Sensors;

namespace {

using common::nao::kPi;  // common/nao/NaoFacts.hpp: one definition, also in a unity build

double clampAbs(double v, double lim) { return std::max(-lim, std::min(lim, v)); }
double towards(double cur, double target, double step) {
  return cur + clampAbs(target - cur, step);
}
// 0..1 -> 0..1, two parabolas: slow start, fast middle, slow landing.
double parabolicStep(double f) {
  f = std::max(0.0, std::min(1.0, f));
  return f < 0.5 ? 2 * f * f : 1 - 2 * (1 - f) * (1 - f);
}
// 0..1 -> 0..1..0: the swing foot's lift profile (a parabola).
double parabolicLift(double f) {
  f = std::max(0.0, std::min(1.0, f));
  return 4 * f * (1 - f);
}
// Gain for a command at `fraction` (0..1) of its limit, from a table at 25,
// 50, 75 and 100 %: linear in between, the 25 % entry below.
double tableGain(const std::array<double, 4>& g, double fraction) {
  const double u = std::max(0.0, std::min(3.0, 4.0 * std::fabs(fraction) - 1.0));
  const int i = std::min(2, static_cast<int>(u));
  return g[i] + (g[i + 1] - g[i]) * (u - i);
}
double smoothBlend(double f) {
  f = std::max(0.0, std::min(1.0, f));
  return 0.5 - 0.5 * std::cos(kPi * f);
}


}  // namespace

double headingRate(const float* s) {
  // Body rates (right-handed, from GyroscopeX/Y/Z with the V5's signs: its
  // GyroscopeZ reads anti-clockwise yaw negative) to the rate of the Euler
  // yaw of R = Rz(yaw) Ry(pitch) Rx(roll), with roll = AngleX and pitch =
  // AngleY. The walk rolls and pitches the torso by a few degrees every
  // step; the bare yaw rate then misreads the heading rate by a few mrad/s.
  const common::libagent::inertial::BodyRates w = common::libagent::inertial::bodyRates(s);
  const double roll = s[S::InertialSensor_AngleX], pitch = s[S::InertialSensor_AngleY];
  const double c = std::cos(pitch);
  if (!(std::fabs(c) > 0.3)) return w.z;  // lying down: not walking anyway
  return (std::sin(roll) * w.y + std::cos(roll) * w.z) / c;
}

WalkSpeed ellipsoidClamp(const WalkSpeed& cmd, const WalkConfig& cfg) {
  WalkSpeed out = cmd;
  if (!std::isfinite(out.forward)) out.forward = 0;
  if (!std::isfinite(out.left)) out.left = 0;
  if (!std::isfinite(out.turn)) out.turn = 0;
  out.turn = clampAbs(out.turn, cfg.max_turn);
  const double t = out.turn / cfg.max_turn;
  const double room = std::sqrt(std::max(0.0, 1.0 - t * t));  // what turn leaves
  const double f = out.forward / cfg.max_forward, l = out.left / cfg.max_left;
  const double r = std::sqrt(f * f + l * l);
  if (r > room) {
    const double s = r > 0 ? room / r : 0.0;
    out.forward *= s;
    out.left *= s;
  }
  return out;
}

WalkSpeed ratchet(const WalkSpeed& current, const WalkSpeed& target, const WalkConfig& cfg) {
  return {towards(current.forward, target.forward, cfg.ratchet_forward),
          towards(current.left, target.left, cfg.ratchet_left),
          towards(current.turn, target.turn, cfg.ratchet_turn)};
}

FootPressure footPressure(const float* s) {
  FootPressure p;
  const int lbase = S::LFoot_FSR_FrontLeft, rbase = S::RFoot_FSR_FrontLeft;
  double moment = 0;
  for (int i = 0; i < 4; ++i) {
    const double fl = std::max(0.0f, s[lbase + i]);
    const double fr = std::max(0.0f, s[rbase + i]);
    p.left += fl;
    p.right += fr;
    // Sensor positions in each ankle frame (common/nao/NaoFacts.hpp), shifted
    // by the hips' offset: y of the centre of pressure about the torso (mm).
    const auto which = static_cast<common::nao::Fsr>(i);
    moment += fl * (NaoDims::kHipOffsetY + common::nao::fsrPosition(common::nao::Side::Left, which).y);
    moment += fr * (-NaoDims::kHipOffsetY + common::nao::fsrPosition(common::nao::Side::Right, which).y);
  }
  p.total = p.left + p.right;
  p.cop_y = p.total > 1e-6 ? moment / p.total : 0.0;
  return p;
}

bool SupportSwitch::shouldSwitch(double t, double T, bool swing_left, const FootPressure& p) const {
  if (t >= cfg_->switch_forced_periods * T) return true;
  if (p.total < cfg_->min_foot_weight) return t >= T;  // nothing to feel: go by time
  if (t < cfg_->switch_min_fraction * T) return false;
  // The weight has crossed to the swing foot's side.
  return swing_left ? p.cop_y > 0 : p.cop_y < 0;
}

Walk2014Generator::Walk2014Generator(const WalkConfig& cfg) : cfg_(cfg), switch_(cfg_) { reset(); }

void Walk2014Generator::reset() {
  state_ = State::Standing;
  want_walk_ = false;
  target_ = step_speed_ = odo_ = WalkSpeed{};
  t_ = 0;
  period_ = cfg_.period;
  height_ = cfg_.stand_hip_height;
  height_timer_ = 0;
  swing_left_ = true;
  steps_ = 0;
  xl_ = xr_ = yl_ = yr_ = th_ = 0;
  xl0_ = xr0_ = yl0_ = yr0_ = th0_ = 0;
  lift_ = 0;
  gyro_x_ = gyro_y_ = 0;
  yaw_measured_ = yaw_time_ = yaw_asked_ = turn_correction_ = 0;
  prev_yaw_measured_ = prev_yaw_time_ = prev_yaw_asked_ = 0;
  ended_fraction_[0] = ended_fraction_[1] = 1.0;
}

void Walk2014Generator::setRequest(bool walk, const WalkSpeed& speed) {
  want_walk_ = walk;
  target_ = walk ? ellipsoidClamp(speed, cfg_) : WalkSpeed{};
}

void Walk2014Generator::beginStep() {
  // When did this swing side's step really end (fraction of its period)?
  if (state_ == State::Walking && t_ > 0 && t_ < cfg_.switch_forced_periods * period_)
    ended_fraction_[swing_left_ ? 0 : 1] = t_ / period_;
  else if (state_ != State::Walking)
    ended_fraction_[0] = ended_fraction_[1] = 1.0;
  if (steps_ == 0 || state_ != State::Walking) {
    // First step: lead with the foot on the side we are going to.
    swing_left_ = !(target_.left < 0 || (target_.left == 0 && target_.turn < 0));
  } else {
    swing_left_ = !swing_left_;
  }
  // Heading hold. The torso yaws one way on every left step and back on
  // every right step (the swing leg's reaction), so a single step's yaw
  // rate is mostly that wobble; the error is taken over the last two steps
  // (one whole walk cycle) and only when both were spent on the ground.
  if (state_ == State::Walking && yaw_time_ > 0.5 * period_ && prev_yaw_time_ > 0.5 * period_) {
    const double measured = (yaw_measured_ + prev_yaw_measured_) / (yaw_time_ + prev_yaw_time_);
    const double asked = (yaw_asked_ + prev_yaw_asked_) / (yaw_time_ + prev_yaw_time_);
    turn_correction_ += cfg_.heading_gain * (asked - measured);
    turn_correction_ = clampAbs(turn_correction_, cfg_.heading_max_correction);
  }
  if (state_ != State::Walking || !want_walk_) {  // starting or stopping: no hold
    turn_correction_ = 0;
    yaw_measured_ = yaw_time_ = yaw_asked_ = 0;
  }
  prev_yaw_measured_ = yaw_measured_;
  prev_yaw_time_ = yaw_time_;
  prev_yaw_asked_ = yaw_asked_;
  yaw_measured_ = yaw_time_ = yaw_asked_ = 0;
  step_speed_ = ratchet(step_speed_, want_walk_ ? target_ : WalkSpeed{}, cfg_);
  period_ = cfg_.period + cfg_.period_side_extra * std::fabs(step_speed_.left) / cfg_.max_left;
  xl0_ = xl_; xr0_ = xr_; yl0_ = yl_; yr0_ = yr_; th0_ = th_;
  t_ = 0;
  lift_ = cfg_.base_lift + cfg_.lift_per_forward * std::fabs(step_speed_.forward) / 1000.0 +
          cfg_.lift_per_left * std::fabs(step_speed_.left) / 1000.0;
  ++steps_;
}

void Walk2014Generator::tick(const common::libagent::SensorValues& sensors, double dt, common::libagent::JointValues& out) {
  odo_ = WalkSpeed{};
  const float* s = sensors.sensors;
  const double f = cfg_.gyro_filter;
  // Roll and pitch rates in rad/s from the calibrated GyroscopeX/Y (the raw
  // GyrX/GyrY counts' sign is not settled: common/libagent/Inertial.hpp).
  const common::libagent::inertial::BodyRates w = common::libagent::inertial::bodyRates(s);
  gyro_x_ = f * gyro_x_ + (1 - f) * w.x;
  gyro_y_ = f * gyro_y_ + (1 - f) * w.y;

  switch (state_) {
    case State::Standing:
      height_ = cfg_.stand_hip_height;
      if (want_walk_) {
        state_ = State::Starting;
        height_timer_ = 0;
      }
      break;
    case State::Starting:
      height_timer_ += dt;
      height_ = cfg_.stand_hip_height +
                (cfg_.walk_hip_height - cfg_.stand_hip_height) * smoothBlend(height_timer_ / cfg_.start_time);
      if (!want_walk_) {
        state_ = State::Stopping;
        height_timer_ = std::max(0.0, cfg_.start_time - height_timer_);
      } else if (height_timer_ >= cfg_.start_time) {
        steps_ = 0;
        beginStep();
        state_ = State::Walking;
      }
      break;
    case State::Walking: {
      t_ += dt;
      const double frac = std::min(1.0, t_ / period_);
      // Horizontal motion (both feet, and the turn) completes by
      // horizontal_fraction of the period; the rest of the step only lowers
      // the swing foot, so when it lands early the feet do not slide
      // against each other while the weight transfers.
      // ... or by the time this side's last step ended, if sooner: in a
      // combined walk the trailing sideways step ends at ~0.91 T, and motion
      // still planned after the switch is lost.
      const double h_end =
          cfg_.adapt_horizontal_to_switch
              ? std::max(cfg_.switch_min_fraction,
                         std::min(cfg_.horizontal_fraction, ended_fraction_[swing_left_ ? 0 : 1]))
              : cfg_.horizontal_fraction;
      const double hfrac = std::min(1.0, frac / h_end);
      const double gain_f = tableGain(cfg_.forward_gains, step_speed_.forward / cfg_.max_forward);
      const double gain_l = tableGain(cfg_.left_gains, step_speed_.left / cfg_.max_left);
      const double F = gain_f * step_speed_.forward * period_;
      const double L = gain_l * step_speed_.left * 2 * period_;
      const double D = (cfg_.turn_gain * step_speed_.turn + turn_correction_) * period_;
      const bool lead = (L > 0 && swing_left_) || (L < 0 && !swing_left_);
      const double y_swing = lead ? L / 2 : 0.0, y_support = lead ? -L / 2 : 0.0;
      // Turning also leads and trails so the feet only ever toe out (toed-in
      // soles collide): the leading step opens both feet to |D|, the
      // trailing step closes them, and the body turns D on each.
      const bool lead_turn = (D > 0 && swing_left_) || (D < 0 && !swing_left_);
      const double th_target = lead_turn ? std::fabs(D) : 0.0;
      const double ps = parabolicStep(hfrac);

      // Support foot (x, y, yaw) before this tick, for odometry.
      const double sx0 = swing_left_ ? xr_ : xl_, sy0 = swing_left_ ? yr_ : yl_;
      const double syaw0 = swing_left_ ? -th_ : th_;
      if (swing_left_) {
        xl_ = xl0_ + (F / 2 - xl0_) * ps;
        yl_ = yl0_ + (y_swing - yl0_) * ps;
        xr_ = xr0_ + (-F / 2 - xr0_) * hfrac;
        yr_ = yr0_ + (y_support - yr0_) * hfrac;
      } else {
        xr_ = xr0_ + (F / 2 - xr0_) * ps;
        yr_ = yr0_ + (y_swing - yr0_) * ps;
        xl_ = xl0_ + (-F / 2 - xl0_) * hfrac;
        yl_ = yl0_ + (y_support - yl0_) * hfrac;
      }
      th_ = th0_ + (th_target - th0_) * ps;
      const double sx1 = swing_left_ ? xr_ : xl_, sy1 = swing_left_ ? yr_ : yl_;
      const double syaw1 = swing_left_ ? -th_ : th_;
      // The body moves opposite to its support foot (relative to the hips).
      odo_.forward = -(sx1 - sx0) / gain_f * cfg_.odometry_forward_scale;
      odo_.left = -(sy1 - sy0) / gain_l * cfg_.odometry_left_scale;
      odo_.turn = -(syaw1 - syaw0) * cfg_.odometry_turn_scale;
      const FootPressure pressure = footPressure(s);
      if (pressure.total >= cfg_.min_foot_weight) {
        const double rate = headingRate(s);
        yaw_measured_ += rate * dt;
        yaw_asked_ += step_speed_.turn * dt;
        yaw_time_ += dt;
        if (cfg_.odometry_turn_from_gyro) odo_.turn = rate * dt;
      }

      if (switch_.shouldSwitch(t_, period_, swing_left_, pressure)) {
        const bool settled = step_speed_.forward == 0 && step_speed_.left == 0 && step_speed_.turn == 0 &&
                             std::fabs(turn_correction_) < 1e-9 &&
                             std::fabs(xl_) < 1 && std::fabs(xr_) < 1 && std::fabs(yl_) < 1 &&
                             std::fabs(yr_) < 1 && std::fabs(th_) < 0.01;
        if (!want_walk_ && settled) {
          state_ = State::Stopping;
          height_timer_ = 0;
          xl_ = xr_ = yl_ = yr_ = th_ = 0;
        } else {
          beginStep();
        }
      }
      break;
    }
    case State::Stopping:
      height_timer_ += dt;
      height_ = cfg_.walk_hip_height +
                (cfg_.stand_hip_height - cfg_.walk_hip_height) * smoothBlend(height_timer_ / cfg_.start_time);
      if (want_walk_) {
        state_ = State::Starting;
        height_timer_ = std::max(0.0, cfg_.start_time - height_timer_);
      } else if (height_timer_ >= cfg_.start_time) {
        state_ = State::Standing;
      }
      break;
  }
  computeLegs(sensors, out);
}

void Walk2014Generator::computeLegs(const common::libagent::SensorValues& sensors, common::libagent::JointValues& out) {
  const bool walking = state_ == State::Walking;
  const double frac = walking ? std::min(1.0, t_ / period_) : 0.0;
  const double lift = walking ? lift_ * parabolicLift(frac) : 0.0;
  // Hip sway toward the support foot moves both feet the other way.
  const double sway = walking ? cfg_.sway * std::sin(kPi * frac) * (swing_left_ ? -1.0 : 1.0) : 0.0;

  feet_.xl = xl_ + cfg_.foot_x_offset;
  feet_.xr = xr_ + cfg_.foot_x_offset;
  const double width = cfg_.stance_width_extra + (walking || state_ == State::Stopping || state_ == State::Starting
                                                       ? cfg_.turn_width * std::fabs(step_speed_.turn)
                                                       : 0.0);
  feet_.yl = yl_ + width - sway;
  feet_.yr = yr_ - width - sway;
  feet_.zl = -height_ + (walking && swing_left_ ? lift : 0.0);
  feet_.zr = -height_ + (walking && !swing_left_ ? lift : 0.0);
  feet_.th = th_;

  // Torso lean: the hip frames pitch forward by `lean`, so targets given in
  // ground-aligned axes turn by Ry(-lean).
  const Mat3 lean = Mat3::rotY(-cfg_.torso_lean);
  FootPose l = footPose(feet_.xl, feet_.yl, feet_.zl, th_);
  FootPose r = footPose(feet_.xr, feet_.yr, feet_.zr, -th_);
  l.position = lean * l.position;
  l.rotation = lean * l.rotation;
  r.position = lean * r.position;
  r.rotation = lean * r.rotation;
  const auto q = legsInverse(l, r);

  double ankle_pitch_fb = cfg_.gyro_pitch_gain * gyro_y_;
  double ankle_roll_fb = cfg_.gyro_roll_gain * gyro_x_;
  // Feedback on the support ankle while stepping, on both when standing.
  const bool fb_left = !walking || !swing_left_;
  const bool fb_right = !walking || swing_left_;

  out.angles[J::LHipYawPitch] = static_cast<float>(q[0].hip_yaw_pitch);
  out.angles[J::LHipRoll] = static_cast<float>(q[0].hip_roll);
  out.angles[J::LHipPitch] = static_cast<float>(q[0].hip_pitch);
  out.angles[J::LKneePitch] = static_cast<float>(q[0].knee);
  out.angles[J::LAnklePitch] = static_cast<float>(q[0].ankle_pitch + (fb_left ? ankle_pitch_fb : 0));
  out.angles[J::LAnkleRoll] = static_cast<float>(q[0].ankle_roll + (fb_left ? ankle_roll_fb : 0));
  out.angles[J::RHipRoll] = static_cast<float>(q[1].hip_roll);
  out.angles[J::RHipPitch] = static_cast<float>(q[1].hip_pitch);
  out.angles[J::RKneePitch] = static_cast<float>(q[1].knee);
  out.angles[J::RAnklePitch] = static_cast<float>(q[1].ankle_pitch + (fb_right ? ankle_pitch_fb : 0));
  out.angles[J::RAnkleRoll] = static_cast<float>(q[1].ankle_roll + (fb_right ? ankle_roll_fb : 0));

  // Arms swing with the opposite leg: left arm forward as the right foot leads.
  out.angles[J::LShoulderPitch] = static_cast<float>(cfg_.arm_pitch - cfg_.arm_swing * xr_);
  out.angles[J::RShoulderPitch] = static_cast<float>(cfg_.arm_pitch - cfg_.arm_swing * xl_);
  out.angles[J::LShoulderRoll] = static_cast<float>(cfg_.arm_roll);
  out.angles[J::RShoulderRoll] = static_cast<float>(-cfg_.arm_roll);
  out.angles[J::LElbowYaw] = -1.2f;
  out.angles[J::RElbowYaw] = 1.2f;
  out.angles[J::LElbowRoll] = -0.4f;
  out.angles[J::RElbowRoll] = 0.4f;
  out.angles[J::LWristYaw] = out.angles[J::RWristYaw] = 0.0f;
  out.angles[J::LHand] = out.angles[J::RHand] = 0.0f;
  for (int i = J::LShoulderPitch; i < J::NUMBER_OF_JOINTS; ++i)
    out.stiffnesses[i] = static_cast<float>(cfg_.stiffness);
  (void)sensors;
}

}  // namespace agent::motion
