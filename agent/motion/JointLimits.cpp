#include "agent/motion/JointLimits.hpp"

#include <algorithm>
#include <cmath>

namespace agent::motion {

void Clipper::clip(common::libagent::JointValues& cmd, const common::libagent::JointValues& sensed, double tick_s) {
  const auto& lim = jointLimits();
  for (int i = 0; i < common::libagent::kNumJoints; ++i) {
    // 1e-5 rad inside the limits: a float at the limit may round past the
    // body side's double-precision limit.
    const float lo = lim[i].lower + 1e-5f, hi = lim[i].upper - 1e-5f;
    float a = cmd.angles[i];
    if (!std::isfinite(a)) a = primed_ ? last_[i] : sensed.angles[i];
    if (!std::isfinite(a)) a = 0.0f;
    a = std::min(hi, std::max(lo, a));
    if (!primed_) {
      // Start where the joint is (itself clamped into range).
      float s = sensed.angles[i];
      if (!std::isfinite(s)) s = 0.0f;
      last_[i] = std::min(hi, std::max(lo, s));
    }
    // A hair under the limit so float rounding never exceeds it.
    const float step = static_cast<float>(lim[i].max_velocity * tick_s) * 0.9999f;
    a = std::min(last_[i] + step, std::max(last_[i] - step, a));
    a = std::min(hi, std::max(lo, a));
    cmd.angles[i] = a;
    last_[i] = a;
    float s = cmd.stiffnesses[i];
    if (!std::isfinite(s)) s = 0.0f;
    cmd.stiffnesses[i] = s < 0.0f ? -1.0f : std::min(1.0f, s);
  }
  primed_ = true;
}

}  // namespace agent::motion
