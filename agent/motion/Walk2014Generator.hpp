// A Walk2014-style omnidirectional walk (rUNSWift's Walk2014 (B. Hengst, 2014 release and report)), written for
// simswift. Open-loop foot trajectories through closed-form leg IK, with
// support-foot switching from the FSRs and gyro feedback on the ankles.
//
// Step geometry (hip frames, mm): a step lasts T. The swing foot moves to
// +F/2 (forward), its target lateral offset and its yaw target while the
// support foot moves linearly to -F/2, so the body advances F = forward * T
// per step. Sideways, the leading foot (left for + left) steps out by L/2
// while the support foot goes to -L/2, and the trailing step brings both back
// to 0: L = left * 2T per cycle. Turning uses one yaw state th (left foot
// +th, right foot -th, as the one HipYawPitch motor dictates); it too leads
// and trails: th opens to |turn| * T on the leading step and closes to 0 on
// the trailing one, so the body turns turn * T per step.
//
// Also the walk's stand: when not stepping it holds the feet together at
// stand height, sinking to walk height before the first step and rising after
// the last.
#pragma once

#include <cstdint>

#include "common/libagent/AgentShared.hpp"
#include "agent/motion/WalkConfig.hpp"

namespace agent::motion {

struct WalkSpeed {
  double forward = 0;  // mm/s
  double left = 0;     // mm/s
  double turn = 0;     // rad/s
};

// Keeps (f/Fmax)^2 + (l/Lmax)^2 + (t/Tmax)^2 <= 1. Turn has priority: it is
// clamped to its own limit first, then forward and left share what is left.
WalkSpeed ellipsoidClamp(const WalkSpeed& cmd, const WalkConfig& cfg);

// Moves `current` toward `target` by at most the config's per-step ratchet.
WalkSpeed ratchet(const WalkSpeed& current, const WalkSpeed& target, const WalkConfig& cfg);

// Lateral centre of pressure (mm, + = left, robot frame between the hips) and
// total weight (kg, the NAO's FSR unit) from the eight FSRs of a libagent
// sensor array.
struct FootPressure {
  double cop_y = 0;  // mm
  double total = 0;  // kg
  double left = 0, right = 0;  // kg per foot
};
FootPressure footPressure(const float* sensors);

// Rate of change of the torso's heading (rad/s, anti-clockwise positive: the
// Euler yaw of Rz(yaw) Ry(AngleY) Rx(AngleX)) from the body rates (GyroscopeX/
// Y/Z with the V5's signs: libagent/Inertial.hpp) and AngleX / AngleY.
double headingRate(const float* sensors);

// Decides when the swing foot has taken the weight: the lateral CoP has
// crossed to the swing side after switch_min_fraction * T, or time is past
// switch_forced_periods * T. Pure logic so it can be tested with synthetic FSRs.
class SupportSwitch {
 public:
  explicit SupportSwitch(const WalkConfig& cfg) : cfg_(&cfg) {}
  // t: time since the step began (s), T: its period (s). swing_left: the
  // swing foot is the left one.
  bool shouldSwitch(double t, double T, bool swing_left, const FootPressure& p) const;

 private:
  const WalkConfig* cfg_;
};

class Walk2014Generator {
 public:
  enum class State { Standing, Starting, Walking, Stopping };

  explicit Walk2014Generator(const WalkConfig& cfg = WalkConfig());

  // The request: walk (stepping, at `speed` after the clamp) or stand.
  void setRequest(bool walk, const WalkSpeed& speed);

  // One 10 ms tick: fills the leg and arm joints of `out` (angles,
  // stiffnesses); leaves the head alone. dt in s.
  void tick(const common::libagent::SensorValues& sensors, double dt, common::libagent::JointValues& out);

  // Restart at stand with feet together (no steps in progress).
  void reset();

  State state() const { return state_; }
  bool stepping() const { return state_ == State::Walking; }
  bool standing() const { return state_ == State::Standing; }
  bool leftIsSwing() const { return swing_left_; }
  const WalkSpeed& latched() const { return step_speed_; }  // this step's speed
  double stepTime() const { return t_; }
  double stepPeriod() const { return period_; }

  // Body motion executed during the last tick, robot frame (mm, mm, rad),
  // from the support foot's motion relative to the hips.
  const WalkSpeed& lastOdometry() const { return odo_; }

  const WalkConfig& config() const { return cfg_; }

  // Foot targets of the last tick (hip frames, mm, rad) for tests.
  struct Feet {
    double xl = 0, yl = 0, zl = 0, xr = 0, yr = 0, zr = 0, th = 0;
  };
  const Feet& feet() const { return feet_; }

 private:
  void beginStep();
  void computeLegs(const common::libagent::SensorValues& sensors, common::libagent::JointValues& out);

  WalkConfig cfg_;
  SupportSwitch switch_;
  State state_ = State::Standing;
  bool want_walk_ = false;
  WalkSpeed target_;      // requested (clamped)
  WalkSpeed step_speed_;  // latched for the current step
  double t_ = 0;          // s since the step began
  double period_ = 0.25;  // s, this step's period
  double height_ = 0;     // mm, current hip height
  double height_timer_ = 0;
  bool swing_left_ = true;
  int64_t steps_ = 0;
  // Foot state (mm / rad) at the start of the step and now.
  double xl0_ = 0, xr0_ = 0, yl0_ = 0, yr0_ = 0, th0_ = 0;
  double xl_ = 0, xr_ = 0, yl_ = 0, yr_ = 0, th_ = 0;
  double lift_ = 0;  // mm, this step's peak lift
  double gyro_x_ = 0, gyro_y_ = 0;  // filtered rad/s
  double yaw_measured_ = 0;    // rad turned this step (headingRate), on the ground
  double yaw_asked_ = 0;       // rad the latched turn asked for over the same time
  double yaw_time_ = 0;        // s of this step spent on the ground
  double prev_yaw_measured_ = 0, prev_yaw_asked_ = 0, prev_yaw_time_ = 0;  // the step before
  double ended_fraction_[2] = {1.0, 1.0};  // last step's end / period, swing left [0] / right [1]
  double turn_correction_ = 0; // rad/s added to the latched turn (heading hold)
  WalkSpeed odo_;
  Feet feet_;
};

}  // namespace agent::motion
