// Names of a robot's named shared objects, as the team's code builds them.
//
// On a NAO there is one robot per machine: libagent opens the bare names
// /libagent-memory and /libagent-semaphore. rUNSWift's simulation build
// appends N = SPL team number x 11 + player number, with no separator
// (rUNSWift 2017 release, robot/libagent): team 19, player 1 -> /libagent-memory210 and
// /libagent-semaphore210. simswift uses that rule by default and the bare
// names for a single robot on request.
//
// Beside the two libagent objects simswift creates its own, which an
// unchanged libagent program never opens: the extension (SimExtension.hpp:
// simulated time, owner pid, attach, camera handshake, shutdown) and, while
// it renders, the camera images (CameraImages.hpp). They take the same
// suffix.
#pragma once

#include <string>

namespace common::libagent {

constexpr const char* kMemoryName = "/libagent-memory";
constexpr const char* kSemaphoreName = "/libagent-semaphore";
constexpr const char* kExtensionName = "/libagent-simswift";
constexpr const char* kImagesName = "/libagent-simswift-images";

// SPL team numbers (the GameController's, one byte) and players (SPL 2017:
// five per team). N = team * 11 + player is unique for players below 11.
constexpr int kMinTeamNumber = 0;
constexpr int kMaxTeamNumber = 255;
constexpr int kMinPlayer = 1;
constexpr int kMaxPlayer = 5;
constexpr int kNameTeamFactor = 11;

struct RobotNames {
  std::string memory, semaphore, extension, images;
};

// N of the simulation-build rule.
inline int simulationNumber(int team, int player) { return team * kNameTeamFactor + player; }

inline RobotNames namesWithSuffix(const std::string& suffix) {
  return {kMemoryName + suffix, kSemaphoreName + suffix, kExtensionName + suffix, kImagesName + suffix};
}
// The simulation build's names (default).
inline RobotNames simulationNames(int team, int player) {
  return namesWithSuffix(std::to_string(simulationNumber(team, player)));
}
// The robot build's bare names (one robot only).
inline RobotNames bareNames() { return namesWithSuffix(""); }

// "t19p1": used in thread names and messages.
inline std::string robotTag(int team, int player) {
  return "t" + std::to_string(team) + "p" + std::to_string(player);
}
// The inverse: "t19p2" -> 19, 2 (false for anything else).
inline bool parseRobotTag(const std::string& tag, int* team, int* player) {
  size_t p = tag.find('p');
  if (tag.size() < 4 || tag[0] != 't' || p == std::string::npos || p == 1 || p + 1 == tag.size()) return false;
  for (size_t i = 1; i < tag.size(); ++i)
    if (i != p && (tag[i] < '0' || tag[i] > '9')) return false;
  if (p - 1 > 3 || tag.size() - p - 1 > 3) return false;  // at most 3 digits each
  *team = std::stoi(tag.substr(1, p - 1));
  *player = std::stoi(tag.substr(p + 1));
  return true;
}

}  // namespace common::libagent
