// Names and layout of a simulated robot's named shared objects.
//
// On a NAO there is one robot per machine, so libagent uses the bare names.
// In simulation every robot gets its own pair, suffixed by
// team * kMaxPlayers + player (facts.md section 2), e.g. team 1 player 2 ->
// "/libagent-memory-8" and "/libagent-semaphore-8".
//
// The shared-memory object holds the AgentBlock first (so a libagent-era
// program that maps only sizeof(AgentBlock) sees exactly what it expects),
// followed by the camera block simswift's Perception handshake uses.
#pragma once

#include <string>

#include "agent/libagent/AgentShared.hpp"
#include "agent/libagent/CameraImages.hpp"
#include "agent/libagent/CameraShared.hpp"

namespace agent::libagent {

struct SimRobotShm {
  AgentBlock agent;
  CameraBlock camera;
};

// Teams 0..1, players 1..kMaxPlayers-1 (SPL 2017: five per team).
constexpr int kMaxTeams = 2;
constexpr int kMinPlayer = 1;
constexpr int kMaxPlayer = kMaxPlayers - 1;

inline int robotSuffix(int team, int player) { return team * kMaxPlayers + player; }
inline std::string memoryName(int team, int player) {
  return std::string(kMemoryName) + "-" + std::to_string(robotSuffix(team, player));
}
inline std::string semaphoreName(int team, int player) {
  return std::string(kSemaphoreName) + "-" + std::to_string(robotSuffix(team, player));
}
// The camera images block (only while the simulator renders).
inline std::string cameraImagesName(int team, int player) {
  return std::string(kCameraImagesName) + "-" + std::to_string(robotSuffix(team, player));
}
// "t1p2": used in thread names and messages.
inline std::string robotTag(int team, int player) {
  return "t" + std::to_string(team) + "p" + std::to_string(player);
}

}  // namespace agent::libagent
