// What libagent does on the NAO beyond passing bytes, as the simulator's
// body side does it, per rUNSWift release (robot/libcommon/libagent.cpp and
// libagent.hpp of the public 2016, 2017 and 2018 releases; numbers below
// are theirs):
//
// - Limp and `standing`. libagent boots limp. It is stiffened by a STIFFEN
//   request in the slot it reads (acted on once, then NONE is written back;
//   2017 and 2018 only: the 2016 block has no stiffen[]) or by a double
//   chest click; stiffening sets `standing = true`, a
//   one-shot flag the program's Effector clears with its next command.
//   While limp or `standing`, the body gets the sit angles at stiffness 0.
//   A double click on a stiff robot makes it limp again; with a foot
//   bumper held, a double click toggles only the head's stiffness.
// - Chest clicks. A click is a press then a release. A series ends when the
//   button has been up for more than kMaxClickInterval cycles; its count n
//   sets bit n-1 of that cycle's ButtonPresses unless libagent keeps it:
//   2 (above), 3 (kill or start the robot program), 4 (restart wifi). A
//   press held more than kShutdownCycles shuts the NAO down. Kept series
//   and the long press are logged here, never passed on.
// - Contact lost (more than kMaxSkips skipped cycles), then limp, which it
//   stays, also once the program answers again, until stiffened:
//   2017, 2018: from the measured angles to a middle pose over 200 cycles
//   at stiffness 1, then to the sit pose over 100 cycles at stiffness 0.2.
//   2016: straight from the measured angles to its own sit pose (other arm
//   angles) at stiffness 1, the head and legs over 200 cycles, the arms
//   twice as fast (100 cycles); no middle pose.
//
// simswift's one addition: `start: stiff` (the thesis's SimulationThread
// set `standing` at start instead of booting limp) holds the scenario's
// posture stiff until the program's first command, `standing` set.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/libagent/AgentShared.hpp"
#include "sim/bridge/Releases.hpp"

namespace simswift::bridge {

enum class StartMode { Stiff, Limp };

class LibagentBehaviour {
 public:
  static constexpr int kMaxClickInterval = 18;  // cycles up that end a click series (MAX_CLICK_INTERVAL)
  static constexpr int kShutdownCycles = 300;   // cycles held down: shut down (3 s)
  static constexpr int kMaxSkips = 50;          // skipped cycles: contact lost (MAX_SKIPS)
  // 2017, 2018: two phases.
  static constexpr int kSitMiddleCycles = 200;  // 0.005 of the sit per cycle
  static constexpr int kSitDownCycles = 100;    // 0.010 per cycle
  static constexpr float kSitMiddleStiffness = 1.0f;
  static constexpr float kSitDownStiffness = 0.2f;
  // 2016: one phase (sit_step += 0.005 per cycle; the arms move by 2 x sit_step).
  static constexpr int kSit2016Cycles = 200;     // head and legs
  static constexpr int kSit2016ArmCycles = 100;  // arms
  static constexpr float kSit2016Stiffness = 1.0f;
  // The release's sit pose and (2017, 2018) the middle pose on the way
  // (rad, libagent joint order); sitMiddleAngles(R2016) is null.
  using Angles = std::array<float, common::libagent::kNumJoints>;
  static const Angles& sitAngles(Release release = Release::R2017);
  static const Angles* sitMiddleAngles(Release release);
  static const Angles& sitMiddleAngles() { return *sitMiddleAngles(Release::R2017); }
  // True for the arm joints (shoulders to hands), which the 2016 sit moves twice as fast.
  static bool isArm(int joint);

  explicit LibagentBehaviour(StartMode start, Release release = Release::R2017);
  Release release() const { return release_; }

  // What the body side writes into `standing` this cycle, if anything.
  struct Standing {
    std::optional<bool> write;
  };

  // The sensor side of one cycle (libagent's postCallback): counts chest
  // clicks. Returns the cycle's ButtonPresses; may ask to set `standing`.
  common::libagent::ButtonPresses onSensors(const common::libagent::SensorValues& v, Standing& standing);
  // A STIFFEN request read from the program's slot (2017, 2018; the 2016
  // block has none, and this logs and ignores one).
  void stiffen(Standing& standing);

  // The joints the body gets this cycle (libagent's preCallback), from the
  // program's latest command (`commanded`: it has sent one), the block's
  // `standing`, whether contact is lost, and the measured angles (rad).
  common::libagent::JointValues body(const common::libagent::JointValues& program, bool commanded, bool standing,
                                    bool contact_lost, const float* measured);

  bool limp() const { return limp_; }
  bool headLimp() const { return head_limp_; }
  bool sitting() const { return sit_cycle_ >= 0; }
  // Things libagent would have said or done (speech, program kill, halt), oldest first.
  std::vector<std::string> takeLog();

 private:
  void series(int clicks, bool bumper, Standing& standing, common::libagent::ButtonPresses& out);
  void sitStep(common::libagent::JointValues& out);  // one cycle of the sit (sit_cycle_ counted already)

  StartMode start_;
  Release release_;
  bool limp_;
  bool head_limp_ = false;
  int sit_cycle_ = -1;  // -1: not sitting
  std::array<float, common::libagent::kNumJoints> sit_from_{};
  int chest_down_ = 0, chest_up_ = 0, presses_ = 0;
  bool shut_down_press_ = false;  // the current press passed kShutdownCycles
  std::vector<std::string> log_;
};

}  // namespace simswift::bridge
