// The simulator's configuration errors as the public API's: the message
// with the file, line and key its throw site gave (Simulation.cpp).
#pragma once

#include "sim/nao_model/RobotModel.hpp"
#include "sim/world/ConfigError.hpp"
#include "simswift/Simulation.hpp"

namespace simswift::api {

ConfigError configError(const simswift::ConfigError& e);
ConfigError configError(const simswift::ModelError& e);  // a URDF's: no key

}  // namespace simswift::api
