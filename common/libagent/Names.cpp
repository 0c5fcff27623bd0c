// Names of the libagent joint and sensor slots, in slot order (rUNSWift 2017 release, robot/libagent
// section 2). Kept beside AgentShared.hpp so the robot code and the simulator
// spell them identically.
#include "common/libagent/AgentShared.hpp"

namespace common::libagent {

namespace Joints {
const char* const kNames[NUMBER_OF_JOINTS] = {
    "HeadYaw",        "HeadPitch",
    "LShoulderPitch", "LShoulderRoll", "LElbowYaw",   "LElbowRoll",  "LWristYaw", "LHand",
    "LHipYawPitch",   "LHipRoll",      "LHipPitch",   "LKneePitch",  "LAnklePitch", "LAnkleRoll",
    "RHipRoll",       "RHipPitch",     "RKneePitch",  "RAnklePitch", "RAnkleRoll",
    "RShoulderPitch", "RShoulderRoll", "RElbowYaw",   "RElbowRoll",  "RWristYaw", "RHand",
};
}  // namespace Joints

namespace Sensors {
const char* const kNames[NUMBER_OF_SENSORS] = {
    "InertialSensor/AccX",          "InertialSensor/AccY",          "InertialSensor/AccZ",
    "InertialSensor/GyrX",          "InertialSensor/GyrY",          "InertialSensor/GyrRef",
    "InertialSensor/AngleX",        "InertialSensor/AngleY",
    "InertialSensor/GyroscopeX",    "InertialSensor/GyroscopeY",    "InertialSensor/GyroscopeZ",
    "InertialSensor/AccelerometerX", "InertialSensor/AccelerometerY",
    "InertialSensor/AccelerometerZ",
    "LFoot/FSR/FrontLeft",          "LFoot/FSR/FrontRight",
    "LFoot/FSR/RearLeft",           "LFoot/FSR/RearRight",
    "LFoot/FSR/CenterOfPressure/X", "LFoot/FSR/CenterOfPressure/Y",
    "RFoot/FSR/FrontLeft",          "RFoot/FSR/FrontRight",
    "RFoot/FSR/RearLeft",           "RFoot/FSR/RearRight",
    "RFoot/FSR/CenterOfPressure/X", "RFoot/FSR/CenterOfPressure/Y",
    "LFoot/Bumper/Left",            "LFoot/Bumper/Right",
    "RFoot/Bumper/Left",            "RFoot/Bumper/Right",
    "ChestBoard/Button",
    "Head/Touch/Front",             "Head/Touch/Rear",              "Head/Touch/Middle",
    "Battery/Charge",               "Battery/Current",
    "US",
};
}  // namespace Sensors

}  // namespace common::libagent
