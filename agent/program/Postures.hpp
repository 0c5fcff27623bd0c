// The named postures are a NAO fact both the robot program and the
// simulator's body side use: agent/nao/Postures.hpp. The program's code
// names them in its own namespace.
#pragma once

#include "agent/nao/Postures.hpp"

namespace agent::program {

using nao::JointArray;
using nao::jointIndex;
using nao::parsePosture;
using nao::Posture;
using nao::postureAngles;
using nao::postureCommand;
using nao::postureName;
using nao::postureNames;
using nao::postureStiffness;

}  // namespace agent::program
