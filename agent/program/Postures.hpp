// The named postures are a NAO fact both the robot program and the
// simulator's body side use: common/nao/Postures.hpp. The program's code
// names them in its own namespace.
#pragma once

#include "common/nao/Postures.hpp"

namespace agent::program {

using common::nao::JointArray;
using common::nao::jointIndex;
using common::nao::parsePosture;
using common::nao::Posture;
using common::nao::postureAngles;
using common::nao::postureCommand;
using common::nao::postureName;
using common::nao::postureNames;
using common::nao::postureStiffness;

}  // namespace agent::program
