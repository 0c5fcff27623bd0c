#include "agent/program/ScriptedMotion.hpp"

#include <algorithm>

#include "common/libagent/Inertial.hpp"


namespace agent::program {

ScriptedMotion::ScriptedMotion(Posture start, std::vector<ScriptStep> steps)
    : cmd_(postureCommand(start)), steps_(std::move(steps)) {
  std::stable_sort(steps_.begin(), steps_.end(),
                   [](const ScriptStep& a, const ScriptStep& b) { return a.t_s < b.t_s; });
}

void ScriptedMotion::tick(const common::libagent::SensorValues& sensors, int64_t sim_time_us,
                          common::libagent::JointValues& out) {
  // Integer microseconds to seconds only for comparison with the script.
  const double t = static_cast<double>(sim_time_us) * 1e-6;
  while (next_ < steps_.size() && steps_[next_].t_s <= t + 1e-9) {
    const ScriptStep& s = steps_[next_++];
    if (s.joint < 0) {
      cmd_ = postureCommand(s.posture);
      ramps_.clear();
      continue;
    }
    if (s.stiffness >= -1) cmd_.stiffnesses[s.joint] = s.stiffness;
    // A new step on a joint replaces that joint's ramp.
    ramps_.erase(std::remove_if(ramps_.begin(), ramps_.end(), [&](const Ramp& r) { return r.joint == s.joint; }),
                 ramps_.end());
    if (s.duration_s > 0)
      ramps_.push_back({s.joint, cmd_.angles[s.joint], s.angle, s.t_s, s.t_s + s.duration_s});
    else
      cmd_.angles[s.joint] = s.angle;
  }
  for (auto it = ramps_.begin(); it != ramps_.end();) {
    const double f = std::clamp((t - it->t0) / (it->t1 - it->t0), 0.0, 1.0);
    cmd_.angles[it->joint] = static_cast<float>(it->from + (it->to - it->from) * f);
    it = f >= 1.0 ? ramps_.erase(it) : it + 1;
  }
  out = cmd_;
  if (ankle_gain_ != 0) {
    namespace J = common::libagent::Joints;
    // First-order low pass, 0.2 per 10 ms tick (time constant ~45 ms), of the
    // pitch rate (GyroscopeY, rad/s, right-handed: common/libagent/Inertial.hpp).
    const float pitch_rate = static_cast<float>(common::libagent::inertial::bodyRates(sensors.sensors).y);
    gyro_filtered_ += 0.2f * (pitch_rate - gyro_filtered_);
    const float d = ankle_gain_ * gyro_filtered_;
    if (out.stiffnesses[J::LAnklePitch] > 0) out.angles[J::LAnklePitch] += d;
    if (out.stiffnesses[J::RAnklePitch] > 0) out.angles[J::RAnklePitch] += d;
  }
}

}  // namespace agent::program
