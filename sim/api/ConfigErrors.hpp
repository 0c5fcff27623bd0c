// The simulator's configuration errors as the public API's: the message
// "file:line: key: message" split into file, line and key (Simulation.cpp).
#pragma once

#include <exception>

#include "simswift/Simulation.hpp"

namespace simswift::api {

ConfigError configError(const std::exception& e);

}  // namespace simswift::api
