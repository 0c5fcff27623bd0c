// The "team's motion code" of this example: a stand-in for a team's own
// Motion (e.g. its Walk2014Generator), written against nothing but the
// libagent value types. It holds the NAO's stand and balances on the
// ankles with the gyroscope, as a walk's balance loop would.
#pragma once

#include "simswift/Types.hpp"

namespace team {

class StandMotion {
 public:
  // gain: s (ankle angle per body rotation rate).
  explicit StandMotion(float ankle_gain = 0.05f) : gain_(ankle_gain) {}

  void tick(const simswift::SensorValues& s, simswift::JointValues& out) {
    using namespace simswift::api;
    for (int j = 0; j < kNumJoints; ++j) {
      out.angles[j] = 0.0f;
      out.stiffnesses[j] = 1.0f;
    }
    out.angles[LShoulderPitch] = out.angles[RShoulderPitch] = 1.5f;  // arms down
    out.angles[LShoulderRoll] = 0.1f;
    out.angles[RShoulderRoll] = -0.1f;
    // Knees bent, the hips and ankles sharing the bend: the torso stays upright.
    const float pitch_rate = s.sensors[GyroscopeY];  // rad/s, forward fall positive
    filtered_ = 0.8f * filtered_ + 0.2f * pitch_rate;
    for (int hip : {LHipPitch, RHipPitch}) out.angles[hip] = -0.4f;
    for (int knee : {LKneePitch, RKneePitch}) out.angles[knee] = 0.8f;
    for (int ankle : {LAnklePitch, RAnklePitch}) out.angles[ankle] = -0.4f + gain_ * filtered_;
  }

 private:
  float gain_;
  float filtered_ = 0.0f;  // rad/s
};

}  // namespace team
