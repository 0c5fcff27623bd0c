#include "sim/bridge/Releases.hpp"

namespace simswift::bridge {

namespace al = common::libagent;

size_t blockSize(Release r) {
  switch (r) {
    case Release::R2016: return sizeof(release::AgentData2016);
    case Release::R2018: return sizeof(release::AgentData2018);
    case Release::R2017: break;
  }
  return sizeof(release::AgentData2017);
}

int releaseYear(Release r) { return static_cast<int>(r); }

bool parseRelease(int year, Release* out) {
  if (year != 2016 && year != 2017 && year != 2018) return false;
  *out = static_cast<Release>(year);
  return true;
}

al::RobotNames releaseNames(Release r, int team, int player, bool bare) {
  if (bare || r == Release::R2016) return al::bareNames();
  if (r == Release::R2018)
    return al::namesWithSuffix(std::to_string(team * release::kNameTeamFactor2018 + player));
  return al::simulationNames(team, player);
}

}  // namespace simswift::bridge
