// The LoLA protocol's facts live in the shared foundation
// (common/lola/Protocol.hpp: the robot program's client reads them too);
// the simulator's LoLA server uses them under its own namespace.
#pragma once

#include "common/lola/Protocol.hpp"

namespace simswift::lola {
using namespace common::lola;
}  // namespace simswift::lola
