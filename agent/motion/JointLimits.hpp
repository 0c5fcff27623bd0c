// NAO V5 joint limits and maximum speeds in libagent order (from
// common/nao/NaoFacts.hpp), and the Clipper that keeps every command inside them.
// Angles rad (Hand: 0..1 fraction open), speeds rad/s (Hand: fraction/s).
#pragma once

#include <array>

#include "common/libagent/AgentShared.hpp"
#include "common/nao/NaoFacts.hpp"

namespace agent::motion {

// The limits themselves are NAO hardware facts (common/nao/NaoFacts.hpp).
using JointLimit = common::nao::JointLimit;
using common::nao::jointLimits;  // indexed by common::libagent::Joints::JointCode

// The NAO V5's Motion tick (s), the default where no clock says otherwise.
constexpr double kMotionTick = common::nao::kMotionTickSeconds;  // s

// Clips commanded angles to the joint limits and to the per-tick speed
// limit, relative to the previous clipped command. The first call (or after
// reset) starts from `sensed` angles, so the first command cannot jump.
class Clipper {
 public:
  // Clips `cmd` in place. `sensed` = the measured angles this tick; commands
  // move at most max_velocity * tick_s (the body's tick: 10 ms on a V5,
  // 12 ms on a V6).
  void clip(common::libagent::JointValues& cmd, const common::libagent::JointValues& sensed, double tick_s = kMotionTick);
  void reset() { primed_ = false; }

 private:
  bool primed_ = false;
  std::array<float, common::libagent::kNumJoints> last_{};
};

}  // namespace agent::motion
