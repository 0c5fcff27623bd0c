// The libagent shared block: the only boundary between the robot code and the
// body it drives (a real NAO through libagent, or simswift).
//
// Layout follows the public rUNSWift libagent (facts.md section 2): four
// triple-buffer indices, three slots each of sensors, button presses, joint
// commands, LEDs, sonar mode and stiffen request, three say-texts and the
// `standing` flag. simswift adds, at the end, a lock-step extension (the
// simulated clock and an acknowledgement semaphore) that a libagent-era robot
// program simply never touches.
//
// Units: angles rad, angular rates rad/s, accelerations m/s^2, forces N,
// distances m (sonar), temperatures deg C, currents A. Frames: NAO torso axes
// (x forward, y left, z up).
#pragma once

#include <semaphore.h>

#include <atomic>
#include <cstdint>

namespace agent::libagent {

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
  float sensors[kNumSensors];
  float sonar[kNumSonars];  // m
};

// Button presses counted since the last read (chest clicks, head touches).
struct ButtonPresses {
  int32_t chest_presses;
  int32_t head_front, head_middle, head_rear;
};

// LED command. Intensities 0..1; colours are RGB triples.
struct LedCommand {
  float left_ear[10];
  float right_ear[10];
  float left_eye[8][3];
  float right_eye[8][3];
  float chest[3];
  float left_foot[3];
  float right_foot[3];
};

// Sonar mode word as written to the US actuator (left/right emitter, period).
using SonarMode = float;

constexpr int kSayTextLength = 128;
constexpr int kSlots = 3;

// simswift's lock-step extension: the simulated clock and acknowledgement.
struct LockStep {
  int64_t sim_time_us;          // simulated time of the sensors in the latest slot
  int64_t tick;                 // 10 ms cycles since the run started
  std::atomic<int32_t> skipped; // cycles whose post was skipped (semaphore > 0)
  // Posted by the robot program after each joint command it writes; the
  // simulator waits on it (with a wall-clock watchdog) before stepping on.
  sem_t motion_done;
  // Set by the simulator when the run ends so robot threads can exit.
  std::atomic<int32_t> shutdown;
  // Set by the robot program once it is attached and its threads wait (the
  // process id, or 1 in-process); the simulator waits for it before tick 0.
  std::atomic<int32_t> attached;
};

constexpr uint32_t kMagic = 0x53574654;  // "SWFT"
constexpr uint32_t kVersion = 1;

struct AgentBlock {
  uint32_t magic;
  uint32_t version;

  // Triple-buffer indices (0..2). Sensors: written by the body side, read by
  // Motion. Actuators (joints, LEDs, sonar, stiffen): written by Motion, read
  // by the body side. The writer fills the slot that is neither latest nor
  // being read, then publishes it as latest; the reader copies latest to read.
  std::atomic<int32_t> sensors_read;
  std::atomic<int32_t> sensors_latest;
  std::atomic<int32_t> actuators_latest;
  std::atomic<int32_t> actuators_read;

  SensorValues sensors[kSlots];
  ButtonPresses buttons[kSlots];
  JointValues joints[kSlots];   // commanded angles and stiffnesses
  LedCommand leds[kSlots];
  SonarMode sonar[kSlots];
  bool stiffen[kSlots];
  char say_text[kSlots][kSayTextLength];
  bool standing;                // robot program's "I am standing" flag

  LockStep lockstep;
};

// Names of the shared objects. On the robot these are the bare names; in
// simulation each robot's are suffixed by (team * kMaxPlayers + player).
constexpr const char* kMemoryName = "/libagent-memory";
constexpr const char* kSemaphoreName = "/libagent-semaphore";
constexpr int kMaxPlayers = 6;

// Returns the picked slot for a writer: neither `latest` nor `being_read`.
inline int freeSlot(int latest, int being_read) {
  for (int s = 0; s < kSlots; ++s)
    if (s != latest && s != being_read) return s;
  return 0;  // unreachable for valid indices
}

}  // namespace agent::libagent
