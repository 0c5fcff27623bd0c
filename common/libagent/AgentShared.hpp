// The libagent shared block: the only boundary between the robot code and the
// body it drives (a real NAO through libagent, or simswift).
//
// AgentData is, byte for byte, the block of the public rUNSWift 2017 release
// (rUNSWift 2017 release, robot/libagent): four uint8_t triple-buffer indices; three slots each
// of sensors, button presses, joint commands, LEDs, sonar mode, stiffen
// request and say-text; the `standing` flag. sizeof = 3284 on x86-64 and
// i386; tests/agent/test_libagent_layout.cpp pins every offset. Nothing is
// appended: what simswift adds lives in a separate object (SimExtension.hpp).
//
// Units, as the NAO reports them (NAOqi / LoLA): angles rad, angular rates
// rad/s, accelerations m/s^2, FSR kg (force / g), centre of pressure m,
// sonar m, temperatures deg C, currents A, battery charge 0..1; the inertial
// slots with the V5's signs and raw counts (Inertial.hpp). NAO torso axes.
#pragma once

#include <cstddef>
#include <cstdint>
namespace common::libagent {

// ---- Joints: the 25 commanded joints in libagent order. There is no
// RHipYawPitch: the hardware drives it from LHipYawPitch's motor.
namespace Joints {
enum JointCode : int {
  HeadYaw = 0, HeadPitch,
  LShoulderPitch, LShoulderRoll, LElbowYaw, LElbowRoll, LWristYaw, LHand,
  LHipYawPitch, LHipRoll, LHipPitch, LKneePitch, LAnklePitch, LAnkleRoll,
  RHipRoll, RHipPitch, RKneePitch, RAnklePitch, RAnkleRoll,
  RShoulderPitch, RShoulderRoll, RElbowYaw, RElbowRoll, RWristYaw, RHand,
  NUMBER_OF_JOINTS
};
// NAO joint names, index = JointCode.
extern const char* const kNames[NUMBER_OF_JOINTS];
}  // namespace Joints
constexpr int kNumJoints = Joints::NUMBER_OF_JOINTS;
static_assert(kNumJoints == 25, "libagent has 25 joint slots");

// ---- Sensors: 37 values in libagent order.
namespace Sensors {
enum SensorCode : int {
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
  ChestBoard_Button,
  Head_Touch_Front, Head_Touch_Rear, Head_Touch_Middle,
  Battery_Charge, Battery_Current,
  US,
  NUMBER_OF_SENSORS
};
extern const char* const kNames[NUMBER_OF_SENSORS];
}  // namespace Sensors
constexpr int kNumSensors = Sensors::NUMBER_OF_SENSORS;
static_assert(kNumSensors == 37, "libagent has 37 sensor slots");

// Sonar echoes: Left0..9 then Right0..9, metres; kSonarNoEcho = nothing seen.
constexpr int kNumSonars = 20;
constexpr float kSonarNoEcho = 2.55f;

// The NAO reports each FSR in kilograms: the force on it (N) over g. The
// eight of a standing robot sum to its mass (about 5.3 kg).
constexpr double kFsrNewtonsPerKilogram = 9.81;  // m/s^2

// Stiffness below this (0, or -1 for "off") leaves the joint limp.
constexpr float kStiffnessLimp = 0.0f;

struct JointValues {
  float angles[kNumJoints];        // rad
  float stiffnesses[kNumJoints];   // 0..1; -1 = off (limp)
  float temperatures[kNumJoints];  // deg C
  float currents[kNumJoints];      // A
};

struct SensorValues {
  JointValues joints;
  float sensors[kNumSensors];  // units above (FSR kg)
  float sonar[kNumSonars];     // m
};

// Button presses: one byte per sensor slot, counted chest-button clicks as
// libagent reports them (rUNSWift 2017 libagent.cpp, doButtons): a series
// of n clicks ends when the button has stayed up for more than 18 cycles,
// and n sets bit n-1 of the next slot. libagent keeps 2, 3 and 4 clicks
// for itself (limp/stiff, start/kill the program, wifi), so a robot program
// sees in practice the single click. Head touches and foot bumpers never
// appear here: they are plain sensor values.
using ButtonPresses = uint8_t;
namespace Buttons {
constexpr ButtonPresses clicks(int n) { return static_cast<ButtonPresses>(1u << (n - 1)); }  // n = 1..8
constexpr ButtonPresses kSingleClick = clicks(1);
}  // namespace Buttons

// One RGB LED (or group) on or off per colour.
struct Rgb {
  bool red, green, blue;
};

// LED command: the ears are 10-bit masks (bit i = ear LED i on), the rest
// RGB triples.
struct LedCommand {
  uint16_t left_ear;
  uint16_t right_ear;
  Rgb left_eye, right_eye, chest, left_foot, right_foot;
};
using LED = LedCommand;

// Sonar mode word as written to the US actuator (left/right emitter, period).
using SonarMode = float;

// Stiffen request: STIFFEN asks the body side to stiffen all joints.
enum StiffenCommand : int32_t { NONE = 0, STIFFEN };

constexpr int kSayTextLength = 35;  // chars per slot, including the terminating 0
constexpr int kSlots = 3;

// The shared block. The indices are volatile bytes as in libagent; both
// sides access them through loadIndex()/storeIndex() (sequentially
// consistent) below.
struct AgentData {
  volatile uint8_t sensors_read;
  volatile uint8_t sensors_latest;
  volatile uint8_t actuators_latest;
  volatile uint8_t actuators_read;

  SensorValues sensors[kSlots];
  ButtonPresses buttons[kSlots];
  JointValues joints[kSlots];   // commanded angles and stiffnesses
  LedCommand leds[kSlots];
  SonarMode sonar[kSlots];
  StiffenCommand stiffen[kSlots];
  char sayTexts[kSlots][kSayTextLength];
  volatile bool standing;       // set by the body side, cleared by the program
};
using AgentBlock = AgentData;

static_assert(sizeof(SensorValues) == 628, "SensorValues is 628 bytes in libagent");
static_assert(sizeof(JointValues) == 400, "JointValues is 400 bytes in libagent");
static_assert(sizeof(LedCommand) == 20, "LED is 20 bytes in libagent");
static_assert(sizeof(StiffenCommand) == 4, "the stiffen enum is 4 bytes in libagent");
static_assert(sizeof(AgentData) == 3284, "AgentData is 3284 bytes in rUNSWift 2017");

// Index access with full ordering: the slot's contents are written before the
// index that publishes it, and read after the index that claims it.
inline uint8_t loadIndex(const volatile uint8_t& i) {
  return __atomic_load_n(const_cast<const uint8_t*>(&i), __ATOMIC_SEQ_CST);
}
inline void storeIndex(volatile uint8_t& i, uint8_t v) {
  __atomic_store_n(const_cast<uint8_t*>(&i), v, __ATOMIC_SEQ_CST);
}
inline bool validSlot(int i) { return i >= 0 && i < kSlots; }

// Returns the slot for a writer: neither `latest` nor `being_read` (either
// may be out of range, e.g. the parked actuators_latest).
inline int freeSlot(int latest, int being_read) {
  for (int s = 0; s < kSlots; ++s)
    if (s != latest && s != being_read) return s;
  return 0;  // unreachable for valid indices
}

}  // namespace common::libagent
