// The LoLA protocol's facts live in the shared foundation
// (agent/lola/Protocol.hpp: the robot program's client reads them too);
// the simulator's LoLA server uses them under its own namespace.
#pragma once

#include "agent/lola/Protocol.hpp"

namespace simswift::lola {
using namespace agent::lola;
}  // namespace simswift::lola
