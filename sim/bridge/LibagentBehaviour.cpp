#include "sim/bridge/LibagentBehaviour.hpp"

#include <algorithm>
#include <cmath>

namespace simswift::bridge {

namespace al = common::libagent;
using Angles = LibagentBehaviour::Angles;

namespace {
constexpr float deg(float d) { return d * static_cast<float>(M_PI) / 180.0f; }
}  // namespace

// Degrees from each release's libagent.hpp (`sit_angles`, and in 2017/2018
// `sit_angles_middle`), libagent joint order: head; left arm; left leg;
// right leg; right arm. The legs are the same in all three; the 2016 arms
// rest lower and rolled in (rUNSWift-2016-release robot/libcommon/libagent.hpp).
const Angles& LibagentBehaviour::sitAngles(Release release) {
  static const Angles a2017 = {0, 0,                                                   // HeadYaw, HeadPitch
                               deg(72), deg(2), deg(-33), deg(-47), deg(55), 0,        // left arm, LHand
                               0, 0, deg(-50), deg(125), deg(-70), 0,                  // LHipYawPitch .. LAnkleRoll
                               0, deg(-50), deg(125), deg(-70), 0,                     // RHipRoll .. RAnkleRoll
                               deg(72), deg(-2), deg(33), deg(47), deg(-55), 0};       // right arm, RHand
  static const Angles a2016 = {0, 0,
                               deg(65), deg(10), deg(-120), deg(-25), deg(15), 0,
                               0, 0, deg(-50), deg(125), deg(-70), 0,
                               0, deg(-50), deg(125), deg(-70), 0,
                               deg(65), deg(-10), deg(120), deg(25), deg(-15), 0};
  return release == Release::R2016 ? a2016 : a2017;
}

const Angles* LibagentBehaviour::sitMiddleAngles(Release release) {
  // Arms forward, so they do not catch on the body on the way down (2017, 2018).
  static const Angles a = {0, 0,
                           deg(70), deg(25), deg(-92), deg(-61), deg(54), 0,
                           0, 0, deg(-50), deg(125), deg(-70), 0,
                           0, deg(-50), deg(125), deg(-70), 0,
                           deg(70), deg(-25), deg(92), deg(61), deg(-54), 0};
  return release == Release::R2016 ? nullptr : &a;
}

bool LibagentBehaviour::isArm(int j) {
  return (j >= al::Joints::LShoulderPitch && j <= al::Joints::LHand) ||
         (j >= al::Joints::RShoulderPitch && j <= al::Joints::RHand);
}

LibagentBehaviour::LibagentBehaviour(StartMode start, Release release)
    : start_(start), release_(release), limp_(start == StartMode::Limp) {}

std::vector<std::string> LibagentBehaviour::takeLog() {
  std::vector<std::string> out;
  out.swap(log_);
  return out;
}

void LibagentBehaviour::series(int clicks, bool bumper, Standing& standing, al::ButtonPresses& out) {
  if (clicks == 2) {
    if (bumper) {
      head_limp_ = !head_limp_;
      log_.push_back(std::string("2 chest clicks with a foot bumper held: head ") + (head_limp_ ? "limp" : "stiff"));
    } else if (limp_) {
      limp_ = false;
      standing.write = true;
      log_.push_back("2 chest clicks: body stiff (standing set)");
    } else {
      limp_ = true;
      sit_cycle_ = -1;
      standing.write = false;
      log_.push_back("2 chest clicks: body limp");
    }
  } else if (clicks == 3) {
    log_.push_back(std::string("3 chest clicks: libagent would ") +
                   (bumper ? "restart NAOqi" : "kill or start the robot program") + " (not passed on)");
  } else if (clicks == 4) {
    log_.push_back("4 chest clicks: libagent would restart the wifi (not passed on)");
  } else if (clicks <= 8) {
    out |= al::Buttons::clicks(clicks);
  } else {
    log_.push_back(std::to_string(clicks) + " chest clicks: more than a byte of ButtonPresses holds (dropped)");
  }
}

al::ButtonPresses LibagentBehaviour::onSensors(const al::SensorValues& v, Standing& standing) {
  namespace S = al::Sensors;
  const bool chest = v.sensors[S::ChestBoard_Button] > 0.5f;
  const bool bumper = v.sensors[S::LFoot_Bumper_Left] > 0.5f || v.sensors[S::LFoot_Bumper_Right] > 0.5f ||
                      v.sensors[S::RFoot_Bumper_Left] > 0.5f || v.sensors[S::RFoot_Bumper_Right] > 0.5f;
  al::ButtonPresses out = 0;
  // A series ends once the button has been up for more than the interval
  // (checked before this cycle's counters move, as libagent does).
  if (chest_up_ > kMaxClickInterval && presses_ > 0) {
    const int n = presses_;
    presses_ = 0;
    series(n, bumper, standing, out);
  }
  if (chest_down_ > kShutdownCycles && !shut_down_press_) {
    shut_down_press_ = true;
    log_.push_back("chest button held 3 s: libagent would shut the NAO down (not passed on)");
  }
  if (chest) {
    ++chest_down_;
    chest_up_ = 0;
  } else {
    ++chest_up_;
    // The long press is not a click (libagent never counts it either).
    if (chest_down_ > 0 && !shut_down_press_) ++presses_;
    chest_down_ = 0;
    shut_down_press_ = false;
  }
  return out;
}

void LibagentBehaviour::stiffen(Standing& standing) {
  if (release_ == Release::R2016) {
    log_.push_back("a STIFFEN request, which rUNSWift 2016's libagent does not have: ignored");
    return;
  }
  limp_ = false;
  standing.write = true;
}

al::JointValues LibagentBehaviour::body(const al::JointValues& program, bool commanded, bool standing,
                                        bool contact_lost, const float* measured) {
  al::JointValues out = program;
  const auto pose = [&](const Angles& a, float stiffness) {
    for (int j = 0; j < al::kNumJoints; ++j) {
      out.angles[j] = a[j];
      out.stiffnesses[j] = stiffness;
    }
  };
  if (start_ == StartMode::Stiff && !commanded && !limp_) {
    // Stiff start: the scenario's posture until the program's first command.
  } else if (limp_ || standing) {
    pose(sitAngles(release_), 0.0f);
  } else if (!contact_lost && sit_cycle_ < 0) {
    // The program's command.
  } else {
    if (sit_cycle_ < 0) {
      sit_cycle_ = 0;
      for (int j = 0; j < al::kNumJoints; ++j) sit_from_[j] = measured[j];
      log_.push_back("lost contact: sitting down");
    }
    ++sit_cycle_;
    sitStep(out);
  }
  if (head_limp_) out.stiffnesses[al::Joints::HeadYaw] = out.stiffnesses[al::Joints::HeadPitch] = 0.0f;
  return out;
}

void LibagentBehaviour::sitStep(al::JointValues& out) {
  const Angles& sit = sitAngles(release_);
  const auto limp = [&] {
    limp_ = true;
    sit_cycle_ = -1;
    for (int j = 0; j < al::kNumJoints; ++j) {
      out.angles[j] = sit[j];
      out.stiffnesses[j] = 0.0f;
    }
    log_.push_back("sat down: limp until stiffened");
  };
  if (release_ == Release::R2016) {
    // One phase. libagent counts in a float (sit_step += 0.005 while < 1);
    // simswift counts whole cycles, so cycle 200 is the sit exactly.
    if (sit_cycle_ > kSit2016Cycles) return limp();
    for (int j = 0; j < al::kNumJoints; ++j) {
      const float k = std::min(1.0f, static_cast<float>(sit_cycle_) / (isArm(j) ? kSit2016ArmCycles : kSit2016Cycles));
      out.angles[j] = (1 - k) * sit_from_[j] + k * sit[j];
      out.stiffnesses[j] = kSit2016Stiffness;
    }
    return;
  }
  const Angles& middle = *sitMiddleAngles(release_);
  if (sit_cycle_ <= kSitMiddleCycles) {
    const float k = static_cast<float>(sit_cycle_) / kSitMiddleCycles;
    for (int j = 0; j < al::kNumJoints; ++j) {
      out.angles[j] = (1 - k) * sit_from_[j] + k * middle[j];
      out.stiffnesses[j] = kSitMiddleStiffness;
    }
  } else if (sit_cycle_ <= kSitMiddleCycles + kSitDownCycles) {
    const float k = static_cast<float>(sit_cycle_ - kSitMiddleCycles) / kSitDownCycles;
    for (int j = 0; j < al::kNumJoints; ++j) {
      out.angles[j] = (1 - k) * middle[j] + k * sit[j];
      out.stiffnesses[j] = kSitDownStiffness;
    }
  } else {
    limp();
  }
}

}  // namespace simswift::bridge
