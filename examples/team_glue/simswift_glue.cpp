// The glue translation unit: the team's headers first (their macros and
// globals: DEG2RAD, MIN/MAX, NONE/ERROR/INFO, Sonar), then simswift's
// public headers, then memcpy between the two layouts, checked here.
#include "simswift_glue.hpp"

#include <cstddef>
#include <cstring>

#include "simswift/Simulation.hpp"

// Same layout, different names: checked once, then memcpy.
static_assert(sizeof(::JointValues) == sizeof(simswift::JointValues), "JointValues layout");
static_assert(sizeof(::SensorValues) == sizeof(simswift::SensorValues), "SensorValues layout");
static_assert(offsetof(::SensorValues, sensors) == offsetof(simswift::SensorValues, sensors), "sensors offset");
static_assert(offsetof(::SensorValues, sonar) == offsetof(simswift::SensorValues, sonar), "sonar offset");
static_assert(static_cast<int>(Joints::NUMBER_OF_JOINTS) == simswift::api::kNumJoints, "joint slots");
static_assert(static_cast<int>(Sensors::NUMBER_OF_SENSORS) == simswift::api::kNumSensors, "sensor slots");
static_assert(static_cast<int>(Sensors::LFoot_FSR_FrontLeft) == simswift::api::LFsrFrontLeft, "FSR slot");
static_assert(static_cast<int>(Sensors::InertialSensor_GyrX) == simswift::api::GyrX, "gyro slot");
static_assert(static_cast<int>(Joints::RHand) == simswift::api::RHand, "joint order");

namespace glue {

Outcome run(const std::string& scenario_yaml, double seconds,
            std::function<void(const SensorValues&, JointValues&)> motion) {
  simswift::Simulation sim = simswift::Simulation::fromYaml(scenario_yaml, "team.yaml");
  Outcome out;
  sim.robot(0).setController([&](const simswift::SensorValues& s, simswift::JointValues& j) {
    ::SensorValues team_s;
    ::JointValues team_j;
    std::memcpy(&team_s, &s, sizeof team_s);
    std::memcpy(&team_j, &j, sizeof team_j);
    motion(team_s, team_j);
    std::memcpy(&j, &team_j, sizeof j);
    out.last = team_s;
  });
  sim.run(seconds);
  out.fallen = sim.robot(0).fallen();
  out.x = sim.robot(0).pose().x;
  out.y = sim.robot(0).pose().y;
  return out;
}

}  // namespace glue
