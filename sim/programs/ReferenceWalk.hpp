// The reference robot program's walk (agent/motion/Walk2014Generator) as a
// bare step, for the public walk test kit's referenceGait()
// (app/api/WalkTest.cpp): app/api may not include the robot program itself.
#pragma once

#include <functional>

#include "common/libagent/AgentShared.hpp"

namespace simswift::programs {

// One Motion tick of a fresh walk: the request (mm/s, mm/s, rad/s; walk
// false: stand), the tick it steps by (s: the robot's body's, 10 ms on a
// V5, 12 ms on a V6), the sensors in, the joint command out.
using ReferenceWalkStep = std::function<void(bool walk, double forward, double left, double turn, double tick_s,
                                             const common::libagent::SensorValues& sensors,
                                             common::libagent::JointValues& joints)>;
ReferenceWalkStep referenceWalk();

}  // namespace simswift::programs
