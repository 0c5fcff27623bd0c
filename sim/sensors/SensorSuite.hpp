// All non-camera sensors of one simulated NAO, computed from the ODE world
// once per 10 ms tick (call update() right after World::step()). The output
// is in libagent order (common/libagent/AgentShared.hpp) and units: rad,
// rad/s, m/s^2 (inertial slots as a V5 gives them: Imu.hpp), N (FSRs;
// copyToAgent() converts them to the NAO's kg), m, deg C, A.
//
// Per-sensor models and conventions live beside their code: Imu.hpp (axes
// and signs), Fsr.hpp, JointEncoders.hpp, Sonar.hpp, Buttons.hpp,
// Battery.hpp; noise in Noise.hpp; parameters in SensorConfig.hpp.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "common/libagent/AgentShared.hpp"
#include "sim/sensors/Battery.hpp"
#include "sim/sensors/Buttons.hpp"
#include "sim/sensors/Fsr.hpp"
#include "sim/sensors/Imu.hpp"
#include "sim/sensors/Noise.hpp"
#include "sim/sensors/SensorConfig.hpp"
#include "sim/sensors/Sonar.hpp"

namespace simswift {
class World;
}

namespace simswift::sensors {

namespace la = common::libagent;

struct SensorReading {
  std::array<float, la::kNumJoints> joint_angles{};        // rad (hands: 0..1 open)
  std::array<float, la::kNumJoints> joint_temperatures{};  // deg C
  std::array<float, la::kNumJoints> joint_currents{};      // A
  std::array<float, la::kNumSensors> sensors{};            // la::Sensors order
  std::array<float, la::kNumSonars> sonar{};               // m, Left0..9, Right0..9
};

// Copies a reading into a libagent sensor slot, in the NAO's units: the
// FSRs go from N to kg (la::kFsrNewtonsPerKilogram), all else (the inertial
// slots too) is already as the NAO reports it. The slot's stiffnesses are left as they are (the
// bridge echoes the commanded ones).
void copyToAgent(const SensorReading& reading, la::SensorValues& out);

class SensorSuite {
 public:
  // Throws SensorConfigError for a bad config, std::runtime_error if the
  // robot's model lacks the ankle joints the FSRs hang from, ModelError if
  // it is not a NAO libagent can read (NaoBinding.hpp).
  SensorSuite(const World& world, int robot, const SensorConfig& config);

  // Reads the world after a step. Ticks are expected consecutively; after a
  // gap (or a teleport: call reset()) the accelerometer restarts from rest.
  void update(const World& world);
  // Forgets velocity history (call after teleporting the robot).
  void reset(const World& world);

  const SensorReading& reading() const { return reading_; }

  void setButton(Button which, bool pressed) { buttons_[static_cast<int>(which)] = pressed; }
  bool button(Button which) const { return buttons_[static_cast<int>(which)]; }
  // The US actuator word last written by the robot program; echoed in the US slot.
  void setSonarMode(float mode) { sonar_mode_ = mode; }

  int robot() const { return robot_; }
  const SensorConfig& config() const { return config_; }

 private:
  void updateJoints(const World& world, double dt);
  void updateImu(const World& world, double dt);
  void updateFeet(const World& world);
  void updateSonar(const World& world);

  int robot_;
  SensorConfig config_;
  SensorReading reading_;

  NoiseStream gyro_noise_, accel_noise_, angle_noise_, encoder_noise_;
  std::array<NoiseStream, 2> fsr_noise_;    // left, right
  std::array<NoiseStream, 2> sonar_noise_;  // left, right

  ImuModel imu_;
  std::array<int, 2> foot_link_{{-1, -1}};  // link of each foot's ankle frame
  std::vector<int> link_foot_;              // per link: 0 left foot, 1 right foot, -1 other
  std::array<FsrLayout, 2> fsr_layout_;
  std::array<bool, la::kNumJoints> is_hand_{};
  std::array<int, la::kNumJoints> joint_of_slot_{};  // model joint of each libagent slot
  std::array<SonarBeam, 2> sonar_beam_;
  std::array<bool, 4> buttons_{};
  float sonar_mode_ = 0;
  Battery battery_;
  int64_t last_tick_ = -1;
};

}  // namespace simswift::sensors
