// Encoding and decoding of the 2017 GameController packets (see the header).
#include "sim/game/GameControlPacket.hpp"

#include <cstring>

namespace simswift::game::spl {

namespace al = common::libagent;

GameControlData encode(const al::GameStateBlock& b, uint8_t packet_number) {
  GameControlData d;
  std::memset(&d, 0, sizeof d);
  std::memcpy(d.header, kDataHeader, sizeof d.header);
  d.version = kDataVersion;
  d.packet_number = packet_number;
  d.players_per_team = kPlayersPerTeam;
  d.game_type = kGameRoundRobin;
  d.state = b.state;
  d.first_half = b.first_half;
  d.kickoff_team = b.kickoff_team;
  d.secondary_state = b.secondary_state;
  d.drop_in_time = kNoDropIn;
  d.secs_remaining = b.secs_remaining;
  d.secondary_time = b.secondary_time;
  for (int t = 0; t < 2; ++t) {
    const al::GameTeamInfo& from = b.teams[t];
    TeamInfo& to = d.teams[t];
    to.team_number = from.team_number;
    to.team_colour = from.team_colour;
    to.score = from.score;
    for (int p = 0; p < al::kGameMaxPlayers && p < kMaxPlayers; ++p) {
      to.players[p].penalty = from.players[p].penalty;
      to.players[p].secs_till_unpenalised = from.players[p].secs_till_unpenalised;
    }
  }
  return d;
}

ReturnData makeReturn(uint8_t team, uint8_t player, ReturnMessage message) {
  ReturnData r;
  std::memcpy(r.header, kReturnHeader, sizeof r.header);
  r.version = kReturnVersion;
  r.team = team;
  r.player = player;
  r.message = static_cast<uint8_t>(message);
  return r;
}

namespace {
// Size, header and version of a packet read off a socket.
template <typename Packet, typename Version>
bool check(const void* bytes, size_t size, const char (&header)[4], Version version, Packet* out, std::string* why) {
  auto no = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  if (size != sizeof(Packet))
    return no(std::to_string(size) + " bytes (expected " + std::to_string(sizeof(Packet)) + ")");
  std::memcpy(out, bytes, sizeof(Packet));
  if (std::memcmp(out->header, header, 4) != 0) return no("header is not " + std::string(header, 4));
  if (out->version != version)
    return no("version " + std::to_string(out->version) + " (expected " + std::to_string(version) + ")");
  return true;
}
}  // namespace

bool decode(const void* bytes, size_t size, GameControlData* out, std::string* why) {
  return check(bytes, size, kDataHeader, kDataVersion, out, why);
}

bool decodeReturn(const void* bytes, size_t size, ReturnData* out, std::string* why) {
  return check(bytes, size, kReturnHeader, kReturnVersion, out, why);
}

}  // namespace simswift::game::spl
