// The LoLA wire protocol of the NAO V6 (2019 onwards): the names, orders and
// lengths both directions use. One home for these facts, part of the shared
// foundation: the robot program's LoLA client (common/lola/LolaConnection.hpp)
// and the simulator's LoLA server (sim/lola) both read them; docs/lola.md says
// which public source gives each (facts.md section 9: B-Human's NaoProvider,
// HULKs' hula, rUNSWift 2019-2022 LoLAData/LoLAEffector, ros-sports/nao_lola).
//
// LoLA's official document is not public; every fact here is from a
// public client or a packet a real robot sent (docs/lola.md, "Sources").
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

namespace common::lola {

// --- Joints: every 25-element array, both directions. No RHipYawPitch:
// index 7 (LHipYawPitch) drives both hips (B-Human, HULKs and nao_lola agree).
constexpr int kNumJoints = 25;
enum Joint : int {
  HeadYaw, HeadPitch,
  LShoulderPitch, LShoulderRoll, LElbowYaw, LElbowRoll, LWristYaw,
  LHipYawPitch, LHipRoll, LHipPitch, LKneePitch, LAnklePitch, LAnkleRoll,
  RHipRoll, RHipPitch, RKneePitch, RAnklePitch, RAnkleRoll,
  RShoulderPitch, RShoulderRoll, RElbowYaw, RElbowRoll, RWristYaw,
  LHand, RHand,
};
extern const std::array<std::string_view, kNumJoints> kJointNames;

// --- FSR (8 values, kg): per foot front-left, front-right, rear-left,
// rear-right; left foot first.
enum Fsr : int {
  LFootFrontLeft, LFootFrontRight, LFootRearLeft, LFootRearRight,
  RFootFrontLeft, RFootFrontRight, RFootRearLeft, RFootRearRight,
};
constexpr int kNumFsrs = 8;

// --- Touch (14 values, 0 or 1 as floats).
enum Touch : int {
  ChestButton, HeadFront, HeadMiddle, HeadRear,
  LFootBumperLeft, LFootBumperRight, LHandBack, LHandLeft, LHandRight,
  RFootBumperLeft, RFootBumperRight, RHandBack, RHandLeft, RHandRight,
};
constexpr int kNumTouch = 14;

// --- Battery (4 values): charge 0..1, status bits (charging: & 0x80),
// current A (negative while discharging), temperature deg C. The order of
// B-Human and HULKs (real-robot clients); nao_lola puts current second.
enum Battery : int { BatteryCharge, BatteryStatus, BatteryCurrent, BatteryTemperature };
constexpr int kNumBattery = 4;

// --- RobotConfig (4 strings): body id, body version, head id, head
// version. Lengths as the real robots give them (HULKs asserts 20-byte ids
// and 5-character versions whose first digit is 6).
enum RobotConfigIndex : int { BodyId, BodyVersion, HeadId, HeadVersion };
constexpr std::array<std::size_t, 4> kRobotConfigLengths{20, 5, 20, 5};

// --- The sensor map: 13 keys, in real LoLA's order: a packet from a real
// V6 quoted in NaoTH's Tools/LolaData.h (github.com/BerlinUnited/NaoTH,
// facts.md section 10). With float32 values, array16 headers for the
// 25-element arrays, Status as positive fixints and RobotConfig as above,
// the map is exactly LoLA's 896 bytes.
enum class SensorKey : int {
  RobotConfig, Accelerometer, Angles, Battery, Current, FSR, Gyroscope,
  Position, Sonar, Stiffness, Temperature, Touch, Status,
};
constexpr int kNumSensorKeys = 13;
struct KeySpec {
  std::string_view name;
  int length;  // array elements
};
extern const std::array<KeySpec, kNumSensorKeys> kSensorKeys;
constexpr std::size_t kSensorPacketBytes = 896;  // every public client reads 896

// --- The actuator map: any subset of these 11 keys, in any order.
enum class ActuatorKey : int {
  Position, Stiffness, Chest, LEye, REye, LEar, REar, LFoot, RFoot, Skull, Sonar,
};
constexpr int kNumActuatorKeys = 11;
extern const std::array<KeySpec, kNumActuatorKeys> kActuatorKeys;
// The key's index, -1 if LoLA has no such actuator key.
int actuatorKeyIndex(std::string_view name);

// LoLA's cycle: 83 Hz, one sensor packet every 12 ms (facts.md 9: Aldebaran's
// NAOqi 2.8 LoLA page; every public client's cycle). The V6 robot's tick.
constexpr long long kCycleUs = 12000;

// Inertial signs: LoLA's value = sign * the physical quantity (torso axes, x
// forward, y left, z up; body rate w right-handed, specific force f =
// acceleration minus gravity, (0, 0, +9.81) upright at rest). The V6
// gyroscope is right-handed, anti-clockwise positive (the V5's Z is the
// opposite); B-Human and HULKs negate all three accelerometer components to
// read f, so LoLA reports -f: upright (0, 0, -9.81) (facts.md 9, docs/lola.md "Signs").
constexpr double kGyroscopeSign[3] = {+1.0, +1.0, +1.0};
constexpr double kAccelerometerSign[3] = {-1.0, -1.0, -1.0};

// LoLA's joint index of each libagent joint slot (common/libagent's order;
// both have 25 joints, LoLA puts the hands last), and back.
int lolaJointOf(int libagent_joint);
int libagentJointOf(int lola_joint);

// The default socket path every unchanged V6 program opens.
constexpr std::string_view kDefaultSocketPath = "/tmp/robocup";

}  // namespace common::lola
