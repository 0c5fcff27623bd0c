#include "sim/programs/ReferenceWalk.hpp"

#include <memory>

#include "agent/motion/Walk2014Generator.hpp"
#include "common/nao/NaoFacts.hpp"

namespace simswift::programs {

ReferenceWalkStep referenceWalk() {
  auto walk = std::make_shared<agent::motion::Walk2014Generator>();
  return [walk](bool on, double forward, double left, double turn, const common::libagent::SensorValues& sensors,
                common::libagent::JointValues& joints) {
    walk->setRequest(on, {forward, left, turn});
    walk->tick(sensors, common::nao::kMotionTickSeconds, joints);
  };
}

}  // namespace simswift::programs
