// The team's own libagent value types (stand-in, global namespace as in
// rUNSWift): libagent 2017's layout under the team's names.
#pragma once

#include "team/defs.hpp"

struct JointValues {
  float angles[Joints::NUMBER_OF_JOINTS];        // rad
  float stiffnesses[Joints::NUMBER_OF_JOINTS];   // 0..1, -1 limp
  float temperatures[Joints::NUMBER_OF_JOINTS];  // deg C
  float currents[Joints::NUMBER_OF_JOINTS];      // A
};

struct SensorValues {
  JointValues joints;
  float sensors[Sensors::NUMBER_OF_SENSORS];
  float sonar[Sonar::NUMBER_OF_READINGS];
};
