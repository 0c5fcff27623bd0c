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
  const double dt = tickLength(time_s);
  const TickInput in = readInputs(sensors, dt);
  startFromLastCommand(sensors, out);
  overrideMode(in);
  const bool stepping = runMode(in, out);
  commandHeadAndClip(in, out);
  last_cmd_ = out;
  integrateOdometry();
  publish(in.req, time_s, stepping);
}

double ActionMotion::tickLength(double time_s) {
  // The tick length from the simulated clock; 10 ms if it did not advance.
  double dt = kMotionTick;
  if (last_time_ >= 0 && time_s > last_time_) dt = std::min(0.1, time_s - last_time_);
  last_time_ = time_s;
  ++ticks_;
  return dt;
}

ActionMotion::TickInput ActionMotion::readInputs(const common::libagent::SensorValues& sensors, double dt) {
  const blackboard::MotionRequest& req = request_;
  if (req.body.type != ActionType::NONE) body_ = req.body;

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
  return TickInput{sensors, req, body_.type, dt, ax, ay, tilt, rate};
}

void ActionMotion::startFromLastCommand(const common::libagent::SensorValues& sensors, common::libagent::JointValues& out) {
  // Start every tick from the previous command (or the measured angles).
  if (!have_last_) {
    last_cmd_ = sensors.joints;
    for (int i = 0; i < common::libagent::kNumJoints; ++i) last_cmd_.stiffnesses[i] = 1.0f;
    have_last_ = true;
  }
  out = last_cmd_;
}

void ActionMotion::overrideMode(const TickInput& in) {
  // Mode changes that override the request: DEAD, and falls.
  if (in.want == ActionType::DEAD) {
    mode_ = Mode::Dead;
  } else if (mode_ != Mode::Falling && mode_ != Mode::Fallen && mode_ != Mode::Getup && mode_ != Mode::Dead &&
             in.tilt > cfg_.fall_angle) {
    startFalling();
  }
}

bool ActionMotion::runMode(const TickInput& in, common::libagent::JointValues& out) {
  switch (mode_) {
    case Mode::Walk: return tickWalk(in, out);
    case Mode::Kick: tickKick(in, out); break;
    case Mode::Crouch: tickCrouch(in, out); break;
    case Mode::Transition: tickTransition(in, out); break;
    case Mode::Limp: tickLimp(in, out); break;
    case Mode::Dead: tickDead(in, out); break;
    case Mode::Falling: tickFalling(in, out); break;
    case Mode::Fallen: tickFallen(in, out); break;
    case Mode::Getup: tickGetup(in, out); break;
  }
  return false;
}

bool ActionMotion::tickWalk(const TickInput& in, common::libagent::JointValues& out) {
  handRequestToWalk(in, out);
  bool stepping = false;
  if (mode_ == Mode::Walk) {
    walk_.tick(in.sensors, in.dt, out);
    stepping = walk_.stepping();
    support_ = walk_.leftIsSwing() ? blackboard::Foot::RIGHT : blackboard::Foot::LEFT;
    posture_ = stepping || walk_.state() != Walk2014Generator::State::Standing ? BodyState::WALKING
                                                                                 : BodyState::STANDING;
  } else if (mode_ == Mode::Kick) {
    runKick(in, out);
  } else if (mode_ == Mode::Crouch) {
    keyframes_.tick(in.dt, out);
    posture_ = BodyState::LIMP;
  }
  return stepping;
}

// Hands the request to the walk, or leaves the walk for a kick, crouch or limp.
void ActionMotion::handRequestToWalk(const TickInput& in, const common::libagent::JointValues& out) {
  switch (in.want) {
    case ActionType::WALK:
      // Picked up (no weight on the feet for a while): stop stepping.
      walk_.setRequest(lifted_time_ < 0.5, WalkSpeed{body_.forward, body_.left, body_.turn});
      break;
    case ActionType::KICK:
      walk_.setRequest(false, {});
      if (walk_.standing() && kick_sequence_ != in.req.sequence) {
        kick_sequence_ = in.req.sequence;
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
}

void ActionMotion::runKick(const TickInput& in, common::libagent::JointValues& out) {
  kick_.tick(in.sensors, in.dt, out);
  support_ = kick_.foot() == blackboard::Foot::RIGHT ? blackboard::Foot::LEFT : blackboard::Foot::RIGHT;
  posture_ = BodyState::KICKING;
}

void ActionMotion::tickKick(const TickInput& in, common::libagent::JointValues& out) {
  runKick(in, out);
  if (kick_.done()) {
    walk_.reset();
    mode_ = Mode::Walk;
  }
}

void ActionMotion::tickCrouch(const TickInput& in, common::libagent::JointValues& out) {
  keyframes_.tick(in.dt, out);
  posture_ = BodyState::LIMP;
  if (in.want != ActionType::CROUCH && in.want != ActionType::LIMP) startTransitionToStand(out);
  if (in.want == ActionType::LIMP) mode_ = Mode::Limp;
}

void ActionMotion::tickTransition(const TickInput& in, common::libagent::JointValues& out) {
  keyframes_.tick(in.dt, out);
  posture_ = BodyState::STANDING;
  if (keyframes_.done()) {
    walk_.reset();
    mode_ = Mode::Walk;
  }
}

void ActionMotion::tickLimp(const TickInput& in, common::libagent::JointValues& out) {
  limpJoints(in.sensors, cfg_.limp_stiffness, out);
  posture_ = BodyState::LIMP;
  if (in.want != ActionType::LIMP) startTransitionToStand(out);
}

void ActionMotion::tickDead(const TickInput& in, common::libagent::JointValues& out) {
  limpJoints(in.sensors, -1.0f, out);
  posture_ = BodyState::LIMP;
  if (in.want != ActionType::DEAD) {
    if (in.tilt > cfg_.fall_angle) {
      startFalling();
    } else {
      startTransitionToStand(out);
    }
  }
}

void ActionMotion::tickFalling(const TickInput& in, common::libagent::JointValues& out) {
  // The safe fall: let go so no motor fights the impact.
  limpJoints(in.sensors, cfg_.falling_stiffness, out);
  posture_ = BodyState::FALLING;
  still_time_ = in.rate < cfg_.settle_rate ? still_time_ + in.dt : 0.0;
  if (still_time_ >= cfg_.settle_time) {
    if (in.tilt > cfg_.fallen_angle) {
      mode_ = Mode::Fallen;
    } else if (in.tilt < cfg_.upright_angle) {
      startTransitionToStand(out);  // caught itself
    } else {
      mode_ = Mode::Fallen;  // leaning on something: treat as down
    }
  }
}

void ActionMotion::tickFallen(const TickInput& in, common::libagent::JointValues& out) {
  limpJoints(in.sensors, cfg_.falling_stiffness, out);
  const bool sideways = std::fabs(in.ax) > std::fabs(in.ay);
  posture_ = sideways ? BodyState::FALLEN_SIDEWAYS : in.ay > 0 ? BodyState::FALLEN_FORWARD : BodyState::FALLEN_BACKWARD;
  const bool asked = in.want == ActionType::GETUP_FRONT || in.want == ActionType::GETUP_BACK;
  if (in.want != ActionType::LIMP && (asked || cfg_.auto_getup) && getups_since_up_ < cfg_.max_getup_attempts) {
    startGetup(in);
  }
}

void ActionMotion::startGetup(const TickInput& in) {
  // Face down (pitched forward, AngleY > 0) gets up from the front. An
  // explicit request wins; sideways goes by the pitch sign as well.
  bool front = in.ay > 0;
  if (in.want == ActionType::GETUP_FRONT) front = true;
  if (in.want == ActionType::GETUP_BACK) front = false;
  JointArray a{};
  for (int i = 0; i < common::libagent::kNumJoints; ++i) a[i] = in.sensors.joints.angles[i];
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

void ActionMotion::tickGetup(const TickInput& in, common::libagent::JointValues& out) {
  keyframes_.tick(in.dt, out);
  out.angles[J::HeadYaw] = 0;
  out.angles[J::HeadPitch] = 0;
  out.stiffnesses[J::HeadYaw] = out.stiffnesses[J::HeadPitch] = 0.8f;
  posture_ = BodyState::GETTING_UP;
  // Rising from the crouch and tipping over: abort into the safe limp fall
  // now rather than finishing the stand; the fall handling retries.
  if (!keyframes_.done() && keyframes_.frame() + cfg_.getup_rise_frames >= keyframes_.frameCount() &&
      in.tilt > cfg_.fall_angle) {
    startFalling();
  } else if (keyframes_.done()) {
    if (in.tilt < cfg_.upright_angle) {
      getups_since_up_ = 0;
      walk_.reset();
      mode_ = Mode::Walk;
      posture_ = BodyState::STANDING;
    } else {
      startFalling();  // it did not work: fall safely and retry
    }
  }
}

void ActionMotion::startFalling() {
  mode_ = Mode::Falling;
  still_time_ = 0;
}

void ActionMotion::commandHeadAndClip(const TickInput& in, common::libagent::JointValues& out) {
  // Head: commanded whenever the body is under control.
  if (mode_ == Mode::Walk || mode_ == Mode::Kick || mode_ == Mode::Crouch || mode_ == Mode::Transition) {
    head_.tick(in.req.head, in.req.sequence, in.sensors, in.dt, out);
  } else {
    head_.reset();
  }

  // Limp modes carry the measured angles; don't let the speed clip drag them.
  if (mode_ == Mode::Falling || mode_ == Mode::Fallen || mode_ == Mode::Dead || mode_ == Mode::Limp) {
    clipper_.reset();
  }
  // The tick in whole us, as the body gives it (10000 on a V5: the same
  // double as kMotionTick, 12000 on a V6).
  clipper_.clip(out, in.sensors.joints, static_cast<double>(std::llround(in.dt * 1e6)) * 1e-6);
}

void ActionMotion::integrateOdometry() {
  // Odometry from the steps the walk executed this tick.
  if (mode_ != Mode::Walk) return;
  const WalkSpeed& d = walk_.lastOdometry();
  odometry_.forward += d.forward;
  odometry_.left += d.left;
  odometry_.turn += d.turn;
  const double mid = odometry_.theta + 0.5 * d.turn;
  odometry_.x += std::cos(mid) * d.forward - std::sin(mid) * d.left;
  odometry_.y += std::sin(mid) * d.forward + std::cos(mid) * d.left;
  odometry_.theta += d.turn;
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
