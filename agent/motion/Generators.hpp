// The Motion thread's other generators: head, keyframe motions (get-ups,
// crouch, transitions), the kick, and dead/limp. Angles rad, times s,
// distances mm (hip frames as in Kinematics.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "agent/blackboard/Blackboard.hpp"
#include "common/libagent/AgentShared.hpp"
#include "agent/motion/WalkConfig.hpp"

namespace agent::motion {

using JointArray = std::array<float, common::libagent::kNumJoints>;

// The walk's standing posture (stand hip height, feet together) as angles.
JointArray walkStandAngles(const WalkConfig& cfg);
// Deep crouch (hip height 160 mm), arms hanging.
JointArray crouchAngles();

// ------------------------------------------------------------------ head

// Moves HeadYaw / HeadPitch toward a target at the commanded speeds (capped
// at the joints' maximum speeds). A relative command is added to the head's
// measured angles once, when a new request sequence arrives.
class HeadGenerator {
 public:
  void tick(const blackboard::HeadCommand& cmd, int64_t sequence, const common::libagent::SensorValues& sensors,
            double dt, common::libagent::JointValues& out);
  void reset() { primed_ = false; }
  float targetYaw() const { return target_yaw_; }

 private:
  bool primed_ = false;
  int64_t last_sequence_ = -1;
  float target_yaw_ = 0, target_pitch_ = 0;
  float yaw_ = 0, pitch_ = 0;  // current command
};

// HeadPitch limits are tighter when the head is turned far (the head hits the
// shoulders): the allowed pitch range (rad) at a given yaw (rad).
void headPitchRange(float yaw, float* lower, float* upper);

// ------------------------------------------------------------------ keyframes

struct Keyframe {
  double duration;       // s to move from the previous frame to this one
  JointArray angles;     // rad
  float stiffness;       // 0..1 for every joint in this frame (legs and arms)
};

// Plays keyframes, interpolating (cosine ease) from the pose it started from.
class KeyframeGenerator {
 public:
  void start(const std::vector<Keyframe>& frames, const JointArray& from);
  // Fills all joints but the head (head too if `with_head`).
  void tick(double dt, common::libagent::JointValues& out, bool with_head = false);
  bool done() const { return frame_ >= frames_.size(); }
  bool active() const { return !frames_.empty() && !done(); }
  double elapsed() const { return elapsed_; }
  size_t frame() const { return frame_; }          // index of the frame being played
  size_t frameCount() const { return frames_.size(); }

 private:
  std::vector<Keyframe> frames_;
  JointArray from_{};
  size_t frame_ = 0;
  double t_ = 0, elapsed_ = 0;
};

// Get-up sequences; each ends in the walk's stand.
std::vector<Keyframe> getupFrontFrames(const WalkConfig& cfg);  // lying face down
std::vector<Keyframe> getupBackFrames(const WalkConfig& cfg);   // lying on the back

// ------------------------------------------------------------------ kick

// A kick as its own motion: shift the hips over the support foot, lift the
// kicking foot, wind back, strike (faster with more power, turned toward the
// direction), retract, put down, shift back to the walk's stand.
struct KickConfig {
  // Tuned in simswift on the NAO's motors (torque-speed line, efficiency 0.8)
  // on noise seeds 600-699 per foot (the tests use 200-239).
  double shift = 70.0;         // mm the hips move sideways over the support foot
  // mm hip height while kicking: the walk's stand. Lower, the support leg's
  // HipRoll cannot reach the 70 mm shift (range ends at 21.7 deg inward).
  double height = 230.0;
  // mm kicking foot lift; at the strike 0.8 of it, which brings the toe's
  // front face (15 mm sole box) up to the ball's centre height: the ball
  // leaves nearly flat (0.2 m/s upward, against 0.45 m/s at 45 mm).
  double lift = 55.0;
  double wind_back = 75.0;     // mm behind the hip at full power (55 mm fell short with the NAO's motor model)
  double reach = 120.0;        // mm ahead of the hip at the strike
  double strike_time_fast = 0.065;  // s at power 1 (the joints' speed limits stretch it: contact ~0.13 s in)
  double strike_time_slow = 0.25;   // s at power 0
  double max_side = 40.0;      // mm the strike may be aimed sideways
  double ankle_roll_margin = 0.03;  // rad the kicking AnkleRoll keeps inside its range
  // rad of ShoulderPitch per mm of kicking-foot x, arms against the leg (see
  // KickGenerator::tick); the arms' range caps it.
  double arm_swing = 0.010;
  double stiffness = 1.0;
};

class KickGenerator {
 public:
  explicit KickGenerator(const WalkConfig& walk_cfg, const KickConfig& cfg = KickConfig())
      : walk_(walk_cfg), cfg_(cfg) {}
  // power 0..1, direction rad (robot frame, 0 = ahead), kicking foot.
  void start(blackboard::Foot foot, double power, double direction);
  void tick(const common::libagent::SensorValues& sensors, double dt, common::libagent::JointValues& out);
  bool done() const { return phase_ >= kPhases; }
  bool active() const { return started_ && !done(); }
  blackboard::Foot foot() const { return foot_; }

 private:
  static constexpr int kPhases = 8;
  struct Target { double x, y, z, shift, height; };
  Target phaseTarget(int phase) const;
  double phaseDuration(int phase) const;

  WalkConfig walk_;
  KickConfig cfg_;
  blackboard::Foot foot_ = blackboard::Foot::RIGHT;
  double power_ = 1, direction_ = 0;
  bool started_ = false;
  int phase_ = kPhases;
  double t_ = 0;
  Target from_{}, now_{};
  double gyro_x_ = 0, gyro_y_ = 0;
};

// ------------------------------------------------------------------ limp

// Holds the measured angles at low stiffness (LIMP): the robot can be posed.
void limpJoints(const common::libagent::SensorValues& sensors, float stiffness, common::libagent::JointValues& out);

}  // namespace agent::motion
