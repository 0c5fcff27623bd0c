#include "common/lola/Protocol.hpp"

#include "common/libagent/AgentShared.hpp"

namespace common::lola {

const std::array<std::string_view, kNumJoints> kJointNames{
    "HeadYaw",        "HeadPitch",
    "LShoulderPitch", "LShoulderRoll", "LElbowYaw",   "LElbowRoll",  "LWristYaw",
    "LHipYawPitch",   "LHipRoll",      "LHipPitch",   "LKneePitch",  "LAnklePitch", "LAnkleRoll",
    "RHipRoll",       "RHipPitch",     "RKneePitch",  "RAnklePitch", "RAnkleRoll",
    "RShoulderPitch", "RShoulderRoll", "RElbowYaw",   "RElbowRoll",  "RWristYaw",
    "LHand",          "RHand",
};

// SensorKey's order (Protocol.hpp: real LoLA's).
const std::array<KeySpec, kNumSensorKeys> kSensorKeys{{
    {"RobotConfig", 4},
    {"Accelerometer", 3},
    {"Angles", 2},
    {"Battery", kNumBattery},
    {"Current", kNumJoints},
    {"FSR", kNumFsrs},
    {"Gyroscope", 3},
    {"Position", kNumJoints},
    {"Sonar", 2},
    {"Stiffness", kNumJoints},
    {"Temperature", kNumJoints},
    {"Touch", kNumTouch},
    {"Status", kNumJoints},
}};

// Lengths: LED counts as B-Human and HULKs write them (Chest/LFoot/RFoot RGB;
// LEye/REye 8 red, 8 green, 8 blue; LEar/REar 10; Skull 12), Sonar 2 enables.
const std::array<KeySpec, kNumActuatorKeys> kActuatorKeys{{
    {"Position", kNumJoints},
    {"Stiffness", kNumJoints},
    {"Chest", 3},
    {"LEye", 24},
    {"REye", 24},
    {"LEar", 10},
    {"REar", 10},
    {"LFoot", 3},
    {"RFoot", 3},
    {"Skull", 12},
    {"Sonar", 2},
}};

int actuatorKeyIndex(std::string_view name) {
  for (int i = 0; i < kNumActuatorKeys; ++i)
    if (kActuatorKeys[i].name == name) return i;
  return -1;
}

namespace {

// Matched by name: both spell the joints alike (common/libagent/Names.cpp).
struct JointTables {
  std::array<int, libagent::kNumJoints> lola_of{};
  std::array<int, kNumJoints> libagent_of{};
  JointTables() {
    for (int j = 0; j < libagent::kNumJoints; ++j)
      for (int l = 0; l < kNumJoints; ++l)
        if (kJointNames[l] == libagent::Joints::kNames[j]) lola_of[j] = l, libagent_of[l] = j;
  }
};
const JointTables& tables() {
  static const JointTables t;
  return t;
}

}  // namespace

int lolaJointOf(int libagent_joint) { return tables().lola_of[libagent_joint]; }
int libagentJointOf(int lola_joint) { return tables().libagent_of[lola_joint]; }

}  // namespace common::lola
