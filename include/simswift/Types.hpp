// simswift's public value types: what a robot's program reads and writes
// each 10 ms tick, in rUNSWift 2017 libagent's layout (SensorValues,
// JointValues: same members, order and units, so a team's own types map by
// memcpy; checked against simswift's block by static_asserts in its
// library), plus poses and the ball in the field frame.
#pragma once

#include <cstdint>

namespace simswift::api {

constexpr int kNumJoints = 25;   // libagent joint slots (HeadYaw .. RHand)
constexpr int kNumSensors = 37;  // libagent sensor slots (AccX .. US)
constexpr int kNumSonars = 20;

// Joint indices (libagent's JointCode order).
enum Joint : int {
  HeadYaw = 0, HeadPitch,
  LShoulderPitch, LShoulderRoll, LElbowYaw, LElbowRoll, LWristYaw, LHand,
  LHipYawPitch, LHipRoll, LHipPitch, LKneePitch, LAnklePitch, LAnkleRoll,
  RHipRoll, RHipPitch, RKneePitch, RAnklePitch, RAnkleRoll,
  RShoulderPitch, RShoulderRoll, RElbowYaw, RElbowRoll, RWristYaw, RHand
};

// Sensor indices (libagent's SensorCode order); units: m/s^2, rad/s, rad,
// FSR kg, centre of pressure m, 0/1 touch, battery 0..1 and A, sonar m.
// The inertial slots are as a NAO V5 gives them (docs/libagent.md,
// "Inertial sensors"): GyroscopeX/Y/Z rad/s with GyroscopeZ NEGATIVE for an
// anti-clockwise turn; AccelerometerX/Y/Z m/s^2 reading -9.81 on Z upright,
// X > 0 leaning forward, Y > 0 leaning right; AngleX/Y rad (roll right,
// pitch forward positive); GyrX/GyrY raw counts (134.6 per rad/s) and
// AccX/Y/Z raw counts (65 per g), GyrRef 0.
enum Sensor : int {
  AccX = 0, AccY, AccZ, GyrX, GyrY, GyrRef, AngleX, AngleY,
  GyroscopeX, GyroscopeY, GyroscopeZ, AccelerometerX, AccelerometerY, AccelerometerZ,
  LFsrFrontLeft, LFsrFrontRight, LFsrRearLeft, LFsrRearRight, LCopX, LCopY,
  RFsrFrontLeft, RFsrFrontRight, RFsrRearLeft, RFsrRearRight, RCopX, RCopY,
  LBumperLeft, LBumperRight, RBumperLeft, RBumperRight,
  ChestButton, HeadTouchFront, HeadTouchRear, HeadTouchMiddle,
  BatteryCharge, BatteryCurrent, Sonar
};

struct JointValues {
  float angles[kNumJoints];        // rad
  float stiffnesses[kNumJoints];   // 0..1; -1 = off (limp)
  float temperatures[kNumJoints];  // deg C (read only)
  float currents[kNumJoints];      // A (read only)
};

struct SensorValues {
  JointValues joints;
  float sensors[kNumSensors];
  float sonar[kNumSonars];  // m (2.55 = no echo)
};

// Field frame: origin at the centre spot, x toward the red goal, z up (m, rad).
struct Pose {
  double x = 0, y = 0, z = 0;  // torso origin
  double theta = 0;            // heading of the torso's x axis
};

struct BallState {
  bool present = false;  // false for `ball: none`
  double x = 0, y = 0, z = 0;     // m
  double vx = 0, vy = 0, vz = 0;  // m/s
};

}  // namespace simswift::api
