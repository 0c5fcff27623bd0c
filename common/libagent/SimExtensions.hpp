// The game state (GameState.hpp) and the team link (TeamLink.hpp) of a
// robot live in its extension object beside the libagent block
// (SimExtension.hpp: /libagent-simswift<N>), so builtin programs (a pointer,
// Runner::extensions(i)) and programs in another process (the named object)
// find them in the same place. This name is kept for the code that reads
// `ext->game` and `ext->team`.
#pragma once

#include "common/libagent/SimExtension.hpp"

namespace common::libagent {

using SimExtensions = SimExtension;

}  // namespace common::libagent
