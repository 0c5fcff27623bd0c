#include "sim/bridge/LibagentBehaviour.hpp"

#include <cmath>

namespace simswift::bridge {

namespace al = agent::libagent;
using Angles = std::array<float, al::kNumJoints>;

namespace {
constexpr float deg(float d) { return d * static_cast<float>(M_PI) / 180.0f; }
}  // namespace

// Degrees from rUNSWift 2017/2018 libagent.hpp (sit_angles, sit_angles_middle),
// libagent joint order: head; left arm; left leg; right leg; right arm.
const Angles& LibagentBehaviour::sitAngles() {
  static const Angles a = {0, 0,                                                   // HeadYaw, HeadPitch
                           deg(72), deg(2), deg(-33), deg(-47), deg(55), 0,        // left arm, LHand
                           0, 0, deg(-50), deg(125), deg(-70), 0,                  // LHipYawPitch .. LAnkleRoll
                           0, deg(-50), deg(125), deg(-70), 0,                     // RHipRoll .. RAnkleRoll
                           deg(72), deg(-2), deg(33), deg(47), deg(-55), 0};       // right arm, RHand
  return a;
}

const Angles& LibagentBehaviour::sitMiddleAngles() {
  // Arms forward, so they do not catch on the body on the way down.
  static const Angles a = {0, 0,
                           deg(70), deg(25), deg(-92), deg(-61), deg(54), 0,
                           0, 0, deg(-50), deg(125), deg(-70), 0,
                           0, deg(-50), deg(125), deg(-70), 0,
                           deg(70), deg(-25), deg(92), deg(61), deg(-54), 0};
  return a;
}

LibagentBehaviour::LibagentBehaviour(StartMode start) : start_(start), limp_(start == StartMode::Limp) {}

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
    pose(sitAngles(), 0.0f);
  } else if (!contact_lost && sit_cycle_ < 0) {
    // The program's command.
  } else {
    if (sit_cycle_ < 0) {
      sit_cycle_ = 0;
      for (int j = 0; j < al::kNumJoints; ++j) sit_from_[j] = measured[j];
      log_.push_back("lost contact: sitting down");
    }
    ++sit_cycle_;
    if (sit_cycle_ <= kSitMiddleCycles) {
      const float k = static_cast<float>(sit_cycle_) / kSitMiddleCycles;
      for (int j = 0; j < al::kNumJoints; ++j) {
        out.angles[j] = (1 - k) * sit_from_[j] + k * sitMiddleAngles()[j];
        out.stiffnesses[j] = kSitMiddleStiffness;
      }
    } else if (sit_cycle_ <= kSitMiddleCycles + kSitDownCycles) {
      const float k = static_cast<float>(sit_cycle_ - kSitMiddleCycles) / kSitDownCycles;
      for (int j = 0; j < al::kNumJoints; ++j) {
        out.angles[j] = (1 - k) * sitMiddleAngles()[j] + k * sitAngles()[j];
        out.stiffnesses[j] = kSitDownStiffness;
      }
    } else {
      limp_ = true;
      sit_cycle_ = -1;
      pose(sitAngles(), 0.0f);
      log_.push_back("sat down: limp until stiffened");
    }
  }
  if (head_limp_) out.stiffnesses[al::Joints::HeadYaw] = out.stiffnesses[al::Joints::HeadPitch] = 0.0f;
  return out;
}

}  // namespace simswift::bridge
