// Stand-in for a team's own base headers (written for this example): the
// kind of macros and globals rUNSWift's code defines (angle and min/max
// macros, log levels as macros, a Sonar namespace, libagent's names for the
// joint and sensor slots). simswift's public headers must compile after
// these (scripts/test-package.sh checks every installed header this way).
#pragma once

#include <cmath>

#define DEG2RAD(x) ((x) * M_PI / 180.0)
#define RAD2DEG(x) ((x) * 180.0 / M_PI)
#define MIN(a, b) ((a) < (b) ? (a) : (b))
#define MAX(a, b) ((a) > (b) ? (a) : (b))
#define NONE 0  // log levels
#define ERROR 1
#define WARNING 2
#define INFO 3
#define VERBOSE 4

// libagent's slot names (2017 order): Joints::HeadYaw .. RHand,
// Sensors::InertialSensor_AccX .. US.
namespace Joints {
enum JointCode {
  HeadYaw = 0, HeadPitch,
  LShoulderPitch, LShoulderRoll, LElbowYaw, LElbowRoll, LWristYaw, LHand,
  LHipYawPitch, LHipRoll, LHipPitch, LKneePitch, LAnklePitch, LAnkleRoll,
  RHipRoll, RHipPitch, RKneePitch, RAnklePitch, RAnkleRoll,
  RShoulderPitch, RShoulderRoll, RElbowYaw, RElbowRoll, RWristYaw, RHand,
  NUMBER_OF_JOINTS
};
}  // namespace Joints

namespace Sensors {
enum SensorCode {
  InertialSensor_AccX = 0, InertialSensor_AccY, InertialSensor_AccZ,
  InertialSensor_GyrX, InertialSensor_GyrY, InertialSensor_GyrRef,
  InertialSensor_AngleX, InertialSensor_AngleY,
  InertialSensor_GyroscopeX, InertialSensor_GyroscopeY, InertialSensor_GyroscopeZ,
  InertialSensor_AccelerometerX, InertialSensor_AccelerometerY, InertialSensor_AccelerometerZ,
  LFoot_FSR_FrontLeft, LFoot_FSR_FrontRight, LFoot_FSR_RearLeft, LFoot_FSR_RearRight,
  LFoot_FSR_CenterOfPressure_X, LFoot_FSR_CenterOfPressure_Y,
  RFoot_FSR_FrontLeft, RFoot_FSR_FrontRight, RFoot_FSR_RearLeft, RFoot_FSR_RearRight,
  RFoot_FSR_CenterOfPressure_X, RFoot_FSR_CenterOfPressure_Y,
  LFoot_Bumper_Left, LFoot_Bumper_Right, RFoot_Bumper_Left, RFoot_Bumper_Right,
  ChestBoard_Button, Head_Touch_Front, Head_Touch_Rear, Head_Touch_Middle,
  Battery_Charge, Battery_Current, US,
  NUMBER_OF_SENSORS
};
}  // namespace Sensors

namespace Sonar {
enum ReadingCode { Left0 = 0, Right0 = 10, NUMBER_OF_READINGS = 20 };
}  // namespace Sonar

extern bool offNao;  // a global, as team code has them
