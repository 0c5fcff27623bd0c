#include "agent/motion/ActionMotion.hpp"

#include <algorithm>
#include <cmath>

#include "common/libagent/Inertial.hpp"

namespace agent::motion {

namespace J = common::libagent::Joints;
namespace S = common::libagent::Sensors;
using blackboard::ActionType;
using blackboard::BodyState;

ActionMotion::ActionMotion(const MotionConfig& cfg)
    : cfg_(cfg), walk_(cfg.walk), kick_(cfg.walk, cfg.kick) {
  body_.type = ActionType::STAND;
}

void ActionMotion::tick(const common::libagent::SensorValues& sensors, int64_t sim_time_us, common::libagent::JointValues& out) {
  tickSeconds(sensors, static_cast<double>(sim_time_us) * 1e-6, out);
}

void ActionMotion::startTransitionToStand(const common::libagent::JointValues& from) {
  JointArray a{};
  for (int i = 0; i < common::libagent::kNumJoints; ++i) a[i] = from.angles[i];
  keyframes_.start({{cfg_.transition_time, walkStandAngles(cfg_.walk), 1.0f}}, a);
  mode_ = Mode::Transition;
}

void ActionMotion::tickSeconds(const common::libagent::SensorValues& sensors, double time_s, common::libagent::JointValues& out) {
  // The tick length from the simulated clock; 10 ms if it did not advance.
  double dt = kMotionTick;
  if (last_time_ >= 0 && time_s > last_time_) dt = std::min(0.1, time_s - last_time_);
  last_time_ = time_s;
  ++ticks_;

  const blackboard::MotionRequest& req = request_;
  if (req.body.type != ActionType::NONE) body_ = req.body;
  const ActionType want = body_.type;

  const float* s = sensors.sensors;
  const double ax = s[S::InertialSensor_AngleX], ay = s[S::InertialSensor_AngleY];
  const double tilt = std::max(std::fabs(ax), std::fabs(ay));
  // Roll and pitch rate magnitude, rad/s, from the calibrated GyroscopeX/Y
  // (common/libagent/Inertial.hpp); float arithmetic as the slots.
  const common::libagent::inertial::BodyRates w = common::libagent::inertial::bodyRates(s);
  const float wx = static_cast<float>(w.x), wy = static_cast<float>(w.y);
  const double rate = std::sqrt(wx * wx + wy * wy);
  const FootPressure feet = footPressure(s);
  lifted_time_ = feet.total < cfg_.lifted_weight ? lifted_time_ + dt : 0.0;

  // Start every tick from the previous command (or the measured angles).
  if (!have_last_) {
    last_cmd_ = sensors.joints;
    for (int i = 0; i < common::libagent::kNumJoints; ++i) last_cmd_.stiffnesses[i] = 1.0f;
    have_last_ = true;
  }
  out = last_cmd_;

  // ---- Mode changes that override the request: DEAD, and falls.
  if (want == ActionType::DEAD) {
    mode_ = Mode::Dead;
  } else if (mode_ != Mode::Falling && mode_ != Mode::Fallen && mode_ != Mode::Getup && mode_ != Mode::Dead &&
             tilt > cfg_.fall_angle) {
    mode_ = Mode::Falling;
    still_time_ = 0;
  }

  bool stepping = false;
  switch (mode_) {
    case Mode::Walk: {
      const WalkSpeed speed{body_.forward, body_.left, body_.turn};
      switch (want) {
        case ActionType::WALK:
          // Picked up (no weight on the feet for a while): stop stepping.
          walk_.setRequest(lifted_time_ < 0.5, speed);
          break;
        case ActionType::KICK:
          walk_.setRequest(false, {});
          if (walk_.standing() && kick_sequence_ != req.sequence) {
            kick_sequence_ = req.sequence;
            kick_.start(body_.foot, body_.kick_power, body_.kick_direction);
            mode_ = Mode::Kick;
          }
          break;
        case ActionType::CROUCH:
          walk_.setRequest(false, {});
          if (walk_.standing()) {
            JointArray a{};
            for (int i = 0; i < common::libagent::kNumJoints; ++i) a[i] = out.angles[i];
            keyframes_.start({{1.0, crouchAngles(), 0.6f}}, a);
            mode_ = Mode::Crouch;
          }
          break;
        case ActionType::LIMP:
          mode_ = Mode::Limp;
          break;
        default:  // STAND, GETUP_* while upright
          walk_.setRequest(false, {});
          break;
      }
      if (mode_ == Mode::Walk) {
        walk_.tick(sensors, dt, out);
        stepping = walk_.stepping();
        support_ = walk_.leftIsSwing() ? blackboard::Foot::RIGHT : blackboard::Foot::LEFT;
        posture_ = stepping || walk_.state() != Walk2014Generator::State::Standing ? BodyState::WALKING
                                                                                     : BodyState::STANDING;
      } else if (mode_ == Mode::Kick) {
        kick_.tick(sensors, dt, out);
        support_ = kick_.foot() == blackboard::Foot::RIGHT ? blackboard::Foot::LEFT : blackboard::Foot::RIGHT;
        posture_ = BodyState::KICKING;
      } else if (mode_ == Mode::Crouch) {
        keyframes_.tick(dt, out);
        posture_ = BodyState::LIMP;
      }
      break;
    }
    case Mode::Kick:
      kick_.tick(sensors, dt, out);
      support_ = kick_.foot() == blackboard::Foot::RIGHT ? blackboard::Foot::LEFT : blackboard::Foot::RIGHT;
      posture_ = BodyState::KICKING;
      if (kick_.done()) {
        walk_.reset();
        mode_ = Mode::Walk;
      }
      break;
    case Mode::Crouch:
      keyframes_.tick(dt, out);
      posture_ = BodyState::LIMP;
      if (want != ActionType::CROUCH && want != ActionType::LIMP) startTransitionToStand(out);
      if (want == ActionType::LIMP) mode_ = Mode::Limp;
      break;
    case Mode::Transition:
      keyframes_.tick(dt, out);
      posture_ = BodyState::STANDING;
      if (keyframes_.done()) {
        walk_.reset();
        mode_ = Mode::Walk;
      }
      break;
    case Mode::Limp:
      limpJoints(sensors, cfg_.limp_stiffness, out);
      posture_ = BodyState::LIMP;
      if (want != ActionType::LIMP) startTransitionToStand(out);
      break;
    case Mode::Dead:
      limpJoints(sensors, -1.0f, out);
      posture_ = BodyState::LIMP;
      if (want != ActionType::DEAD) {
        if (tilt > cfg_.fall_angle) {
          mode_ = Mode::Falling;
          still_time_ = 0;
        } else {
          startTransitionToStand(out);
        }
      }
      break;
    case Mode::Falling:
      // The safe fall: let go so no motor fights the impact.
      limpJoints(sensors, cfg_.falling_stiffness, out);
      posture_ = BodyState::FALLING;
      still_time_ = rate < cfg_.settle_rate ? still_time_ + dt : 0.0;
      if (still_time_ >= cfg_.settle_time) {
        if (tilt > cfg_.fallen_angle) {
          mode_ = Mode::Fallen;
        } else if (tilt < cfg_.upright_angle) {
          startTransitionToStand(out);  // caught itself
        } else {
          mode_ = Mode::Fallen;  // leaning on something: treat as down
        }
      }
      break;
    case Mode::Fallen: {
      limpJoints(sensors, cfg_.falling_stiffness, out);
      const bool sideways = std::fabs(ax) > std::fabs(ay);
      posture_ = sideways ? BodyState::FALLEN_SIDEWAYS : ay > 0 ? BodyState::FALLEN_FORWARD : BodyState::FALLEN_BACKWARD;
      const bool asked = want == ActionType::GETUP_FRONT || want == ActionType::GETUP_BACK;
      if (want != ActionType::LIMP && (asked || cfg_.auto_getup) && getups_since_up_ < cfg_.max_getup_attempts) {
        // Face down (pitched forward, AngleY > 0) gets up from the front. An
        // explicit request wins; sideways goes by the pitch sign as well.
        bool front = ay > 0;
        if (want == ActionType::GETUP_FRONT) front = true;
        if (want == ActionType::GETUP_BACK) front = false;
        JointArray a{};
        for (int i = 0; i < common::libagent::kNumJoints; ++i) a[i] = sensors.joints.angles[i];
        const std::vector<Keyframe>& custom = front ? cfg_.getup_front : cfg_.getup_back;
        keyframes_.start(!custom.empty() ? custom
                         : front         ? getupFrontFrames(cfg_.walk)
                                         : getupBackFrames(cfg_.walk),
                         a);
        ++getup_attempts_;
        ++getups_since_up_;
        getup_front_ = front;
        mode_ = Mode::Getup;
      }
      break;
    }
    case Mode::Getup:
      keyframes_.tick(dt, out);
      out.angles[J::HeadYaw] = 0;
      out.angles[J::HeadPitch] = 0;
      out.stiffnesses[J::HeadYaw] = out.stiffnesses[J::HeadPitch] = 0.8f;
      posture_ = BodyState::GETTING_UP;
      // Rising from the crouch and tipping over: abort into the safe limp fall
      // now rather than finishing the stand; the fall handling retries.
      if (!keyframes_.done() && keyframes_.frame() + cfg_.getup_rise_frames >= keyframes_.frameCount() &&
          tilt > cfg_.fall_angle) {
        mode_ = Mode::Falling;
        still_time_ = 0;
      } else if (keyframes_.done()) {
        if (tilt < cfg_.upright_angle) {
          getups_since_up_ = 0;
          walk_.reset();
          mode_ = Mode::Walk;
          posture_ = BodyState::STANDING;
        } else {
          mode_ = Mode::Falling;  // it did not work: fall safely and retry
          still_time_ = 0;
        }
      }
      break;
  }

  // Head: commanded whenever the body is under control.
  if (mode_ == Mode::Walk || mode_ == Mode::Kick || mode_ == Mode::Crouch || mode_ == Mode::Transition) {
    head_.tick(req.head, req.sequence, sensors, dt, out);
  } else {
    head_.reset();
  }

  // Limp modes carry the measured angles; don't let the speed clip drag them.
  if (mode_ == Mode::Falling || mode_ == Mode::Fallen || mode_ == Mode::Dead || mode_ == Mode::Limp) {
    clipper_.reset();
  }
  // The tick in whole us, as the body gives it (10000 on a V5: the same
  // double as kMotionTick, 12000 on a V6).
  clipper_.clip(out, sensors.joints, static_cast<double>(std::llround(dt * 1e6)) * 1e-6);
  last_cmd_ = out;

  // Odometry from the steps the walk executed this tick.
  if (mode_ == Mode::Walk) {
    const WalkSpeed& d = walk_.lastOdometry();
    odometry_.forward += d.forward;
    odometry_.left += d.left;
    odometry_.turn += d.turn;
    const double mid = odometry_.theta + 0.5 * d.turn;
    odometry_.x += std::cos(mid) * d.forward - std::sin(mid) * d.left;
    odometry_.y += std::sin(mid) * d.forward + std::cos(mid) * d.left;
    odometry_.theta += d.turn;
  }
  publish(req, time_s, stepping);
}

void ActionMotion::publish(const blackboard::MotionRequest& req, double time_s, bool stepping) {
  blackboard::MotionState st;
  st.odometry = odometry_;
  st.posture = posture_;
  st.support_foot = support_;
  switch (mode_) {
    case Mode::Walk: st.active = walk_.standing() ? ActionType::STAND : ActionType::WALK; break;
    case Mode::Kick: st.active = ActionType::KICK; break;
    case Mode::Crouch: st.active = ActionType::CROUCH; break;
    case Mode::Transition: st.active = ActionType::STAND; break;
    case Mode::Limp: st.active = ActionType::LIMP; break;
    case Mode::Dead:
    case Mode::Falling:
    case Mode::Fallen: st.active = ActionType::DEAD; break;
    case Mode::Getup:
      st.active = getup_front_ ? ActionType::GETUP_FRONT : ActionType::GETUP_BACK;
      break;
  }
  st.walk_stepping = stepping;
  st.request_sequence = req.sequence;
  st.tick = ticks_;
  st.time = time_s;
  state_ = st;
}

}  // namespace agent::motion
