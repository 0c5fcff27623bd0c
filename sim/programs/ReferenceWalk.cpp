#include "sim/programs/ReferenceWalk.hpp"

#include <memory>

#include "agent/motion/Walk2014Generator.hpp"
#include "agent/nao/NaoFacts.hpp"

namespace simswift::programs {

ReferenceWalkStep referenceWalk() {
  auto walk = std::make_shared<agent::motion::Walk2014Generator>();
  return [walk](bool on, double forward, double left, double turn, const agent::libagent::SensorValues& sensors,
                agent::libagent::JointValues& joints) {
    walk->setRequest(on, {forward, left, turn});
    walk->tick(sensors, agent::nao::kMotionTickSeconds, joints);
  };
}

}  // namespace simswift::programs
