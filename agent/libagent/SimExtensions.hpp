// The simulator's per-robot extension objects, beside the libagent block:
// the game state (GameState.hpp) and the team link (TeamLink.hpp). One block
// per robot. Builtin robot programs share the runner's process and get a
// pointer (Runner::extensions(i)); a program in another process would map
// extensionsName(team, player) (not created yet: see README).
#pragma once

#include <string>

#include "agent/libagent/GameState.hpp"
#include "agent/libagent/SharedNames.hpp"
#include "agent/libagent/TeamLink.hpp"

namespace agent::libagent {

constexpr uint32_t kSimExtensionsMagic = 0x53575845;  // "SWXE"
constexpr const char* kSimExtensionsName = "/simswift-extensions";

struct SimExtensions {
  uint32_t magic = kSimExtensionsMagic;
  GameStateBlock game{};
  TeamLink team;
};

// Suffixed like the libagent block (SharedNames.hpp: N = team x 11 + player).
inline std::string extensionsName(int team, int player) {
  return std::string(kSimExtensionsName) + std::to_string(simulationNumber(team, player));
}

}  // namespace agent::libagent
