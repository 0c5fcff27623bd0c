#include "sim/programs/ReferenceWalk.hpp"

#include <memory>

#include "agent/motion/Walk2014Generator.hpp"

namespace simswift::programs {

ReferenceWalkStep referenceWalk() {
  auto walk = std::make_shared<agent::motion::Walk2014Generator>();
  return [walk](bool on, double forward, double left, double turn, double tick_s,
                const common::libagent::SensorValues& sensors, common::libagent::JointValues& joints) {
    walk->setRequest(on, {forward, left, turn});
    walk->tick(sensors, tick_s, joints);
  };
}

}  // namespace simswift::programs
