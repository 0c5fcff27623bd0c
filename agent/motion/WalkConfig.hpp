// Every parameter of the Walk2014-style walk in one typed struct, with units.
// Defaults follow rUNSWift's Walk2014 (B. Hengst, 2014 release and report) except where a comment says otherwise.
// Units: mm, mm/s, rad, rad/s, s, kg (FSRs, as the NAO reports them).
#pragma once

#include <array>

#include "common/libagent/AgentShared.hpp"

namespace agent::motion {

struct WalkConfig {
  // --- Timing
  double period = 0.25;            // s, one step (half a walk cycle)
  double period_side_extra = 0.1;  // s added at full sideways speed (x |left|/max_left)

  // --- Limits (the ellipsoid clamp's semi-axes; turn keeps priority)
  double max_forward = 300.0;  // mm/s
  double max_left = 200.0;     // mm/s
  double max_turn = 0.8;       // rad/s

  // --- Per-step ratchet: the most the latched command may change from one
  // step to the next (speed units per step).
  double ratchet_forward = 60.0;  // mm/s per step
  double ratchet_left = 50.0;     // mm/s per step
  double ratchet_turn = 0.25;     // rad/s per step

  // --- Heights (hip joint above the sole, mm)
  double walk_hip_height = 210.0;
  // rUNSWift's Walk2014 gives 248 mm for its stand, which is a straight leg here
  // (248.09 mm); 230 mm keeps the knees bent so the servos can absorb.
  double stand_hip_height = 230.0;
  double start_time = 0.5;  // s to sink from stand to walk height (and to rise)

  // --- Swing foot lift (mm): base + per (m/s) of forward and sideways speed,
  // i.e. 0.014 m + 0.01 m per m/s forward + 0.02 m per m/s sideways.
  double base_lift = 14.0;
  double lift_per_forward = 10.0;  // mm per (m/s)
  double lift_per_left = 20.0;     // mm per (m/s)

  // --- Stance (added to every foot target, hip frame, mm)
  double foot_x_offset = 0.0;       // + = feet ahead of the hips
  double stance_width_extra = 0.0;  // + = feet further apart than the hips
  double torso_lean = 0.0;          // rad, + = torso pitched forward (soles pitched back)
  // Sideways hip sway toward the support foot (mm, peak). Walk2014 relies on
  // the gait's own rocking; 0 keeps it that way.
  double sway = 0.0;

  // --- Support-foot switching from the FSRs' lateral centre of pressure
  double switch_min_fraction = 0.75;  // of the period before a CoP sign change counts
  // Fraction of the step period in which the feet finish their horizontal
  // motion (step length, sideways step, turn); the remainder only lowers
  // the swing foot. Walk2014 moves the support foot until the very end
  // (1.0); the FSR switch fires at ~0.94 T, so a little before that the
  // swing foot is already where it lands. Measured on bench seeds 1-3 with
  // all gains 1.0 (forward / left at 100 %): 1.0 -> 0.97 / 0.89, 0.97 ->
  // 1.02 / 0.95, 0.95 -> 1.04 / 0.95, 0.9 -> 1.11 / 1.04.
  double horizontal_fraction = 0.97;
  // Finish the horizontal motion by when this swing side's last step ended,
  // if that was sooner (never before switch_min_fraction).
  bool adapt_horizontal_to_switch = true;
  double switch_forced_periods = 3.0; // switch regardless after this many periods
  // kg on both feet together to trust the FSRs (2 N); below it (robot
  // lifted) switch on time (1 period)
  double min_foot_weight = 2.0 / common::libagent::kFsrNewtonsPerKilogram;

  // --- Gyro balance feedback on the support ankle
  double gyro_filter = 0.8;        // filtered = f * filtered + (1 - f) * gyro
  double gyro_pitch_gain = 1.0 / 25.0;  // rad of ankle pitch per rad/s of GyroscopeY (pitch rate)
  double gyro_roll_gain = 1.0 / 25.0;   // rad of ankle roll per rad/s of GyroscopeX (roll rate)

  // --- Arms
  double arm_swing = 0.006;        // rad of shoulder pitch per mm of the opposite foot's x
  double arm_pitch = 1.5;          // rad, arms hanging (ShoulderPitch)
  double arm_roll = 0.15;          // rad, away from the body (mirrored on the right)

  // Feet apart by this much more per rad/s of turn (mm per rad/s, each
  // side): toed-in feet otherwise touch (the sole gap is only 11 mm).
  double turn_width = 0.0;  // 0: turning only toes out (lead/trail), no collision

  // --- Calibration: what a team measures on its own robot (step length
  // achieved / commanded, per axis). No simulator compensation here: with
  // the current body model (motors, sole contacts, joint projection) the walk reaches its command uncalibrated, so
  // every entry is 1.0 (bench_motion prints achieved / commanded). A team
  // would set one factor per axis from its robot's measurements; keep any
  // such factor within 10 % of 1 (beyond that the walk itself is wrong).
  // The forward and sideways tables are over the commanded fraction of
  // max_forward / max_left: at 25, 50, 75 and 100 %, linear in between.
  std::array<double, 4> forward_gains{1.0, 1.0, 1.0, 1.0};
  std::array<double, 4> left_gains{1.0, 1.0, 1.0, 1.0};
  double turn_gain = 1.0;
  // Odometry is the commanded (pre-gain) step times these. The foot
  // geometry says 1: the body moves opposite to its support foot, and a
  // support foot yawing by d turns the body by d (about whatever point).
  double odometry_forward_scale = 1.0;
  double odometry_left_scale = 1.0;
  double odometry_turn_scale = 1.0;

  // --- Heading hold: the heading rate (headingRate(): GyroscopeX/Y/Z with
  // AngleX / AngleY, the Euler yaw rate) measured over the last two steps
  // (one walk cycle: the torso yaws one way on left steps and back on right
  // steps, so one step's rate is mostly that wobble) is compared with the
  // turn asked over them; a fraction of the error is added to the next
  // steps' turn (rad/s), up to a limit. Slipping feet otherwise make a
  // straight walk curve. Only while the feet carry weight.
  // 0.7: tried 0.15 / 0.3 / 0.5 / 0.7 / 1.0 on seeds 40-49 (forward 200 +
  // left +-100, 150 + 50, 250 + 100, 10 s): 0.7 held the heading best; 1.0
  // starts to overshoot from cycle to cycle.
  double heading_gain = 0.7;          // of the cycle's rate error (rad/s), per step
  double heading_max_correction = 0.6;  // rad/s (0.3 capped the 0.8 rad/s turn at 88 %)
  // Odometry turn from headingRate() while stepping on the ground; from
  // the feet (x odometry_turn_scale) otherwise.
  bool odometry_turn_from_gyro = true;

  double stiffness = 1.0;  // leg and arm stiffness while walking
};

}  // namespace agent::motion
