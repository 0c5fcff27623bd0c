#include "sim/game/GameControlVersions.hpp"

#include <cstring>

#include "sim/game/GameControlPacket.hpp"

namespace simswift::game::spl {

namespace al = common::libagent;

namespace {

// Sizes: an 18-byte head (header 4, version, packet number, players per
// team, competition phase and type, game phase, state, set play, first
// half, kicking team: 1 each; seconds remaining and secondary time: int16),
// then two TeamInfos: 6 bytes (2019-2021: number, colour, score, penalty
// shots, single shots u16), 8 (2022: + message budget u16) or 10 (2023 on:
// number, field player colour, goalkeeper colour, goalkeeper, score,
// penalty shots, single shots, message budget), and 2 bytes per player slot.
constexpr std::size_t kHead = 18;
constexpr std::size_t teamBytes(int players, bool budget, bool goalkeeper) {
  return (goalkeeper ? 10 : budget ? 8 : 6) + 2 * static_cast<std::size_t>(players);
}
constexpr std::size_t dataBytes(int players, bool budget, bool goalkeeper) {
  return kHead + 2 * teamBytes(players, budget, goalkeeper);
}

const std::vector<PacketVersion> kVersions = {
    {10, "2017-2018", kMaxPlayers, kPlayersPerTeam, false, false, kReturnVersion, sizeof(GameControlData),
     sizeof(ReturnData)},
    {12, "2019", 6, 5, false, false, 3, dataBytes(6, false, false), 8},
    {13, "2020-2021", 6, 5, false, false, 3, dataBytes(6, false, false), 8},
    {14, "2022", 7, 5, true, false, 4, dataBytes(7, true, false), 32},
    {15, "2023", 20, 7, true, true, 4, dataBytes(20, true, true), 32},
    {17, "2024", 20, 7, true, true, 4, dataBytes(20, true, true), 32},
    {18, "2025", 20, 7, true, true, 4, dataBytes(20, true, true), 32},
};

struct Writer {
  std::vector<std::uint8_t>& out;
  void u8(unsigned v) { out.push_back(static_cast<std::uint8_t>(v)); }
  void u16(unsigned v) {
    u8(v & 0xff);
    u8((v >> 8) & 0xff);
  }
};

}  // namespace

const std::vector<PacketVersion>& packetVersions() { return kVersions; }

const PacketVersion* findPacketVersion(int data_version) {
  for (const PacketVersion& v : kVersions)
    if (v.data_version == data_version) return &v;
  return nullptr;
}

std::string packetVersionList() {
  std::string s;
  for (const PacketVersion& v : kVersions)
    s += (s.empty() ? "" : ", ") + std::to_string(v.data_version) + " (" + v.seasons + ")";
  return s;
}

int penaltyCode(const PacketVersion& v, al::Penalty p) {
  if (v.data_version <= 12) return static_cast<int>(p);
  switch (p) {
    case al::Penalty::IllegalDefender: return 5;   // PENALTY_SPL_ILLEGAL_POSITION
    case al::Penalty::KickOffGoal: return -1;      // no such penalty from 2020
    case al::Penalty::RequestForPickup: return 7;  // PENALTY_SPL_REQUEST_FOR_PICKUP
    default: return static_cast<int>(p);           // 0-4, 6, 14, 15: the same numbers
  }
}

std::vector<std::uint8_t> encodeGameData(const PacketVersion& v, const al::GameStateBlock& b,
                                         std::uint8_t packet_number, std::uint16_t message_budget) {
  std::vector<std::uint8_t> out;
  if (v.data_version == kDataVersion) {  // 2017: the struct as it is
    const GameControlData d = encode(b, packet_number);
    const auto* p = reinterpret_cast<const std::uint8_t*>(&d);
    return {p, p + sizeof d};
  }
  out.reserve(v.data_bytes);
  Writer w{out};
  for (char c : kDataHeader) w.u8(static_cast<unsigned char>(c));
  w.u8(static_cast<unsigned>(v.data_version));
  w.u8(packet_number);
  w.u8(static_cast<unsigned>(v.players_per_team));
  w.u8(0);                  // competition phase: round robin
  w.u8(0);                  // competition type: normal
  w.u8(b.secondary_state);  // game phase: the 2017 secondary state's numbers
  w.u8(b.state);
  w.u8(0);  // set play: none
  w.u8(b.first_half);
  w.u8(b.kickoff_team);
  w.u16(b.secs_remaining);  // int16 on the wire: the half's seconds fit
  w.u16(b.secondary_time);
  for (const al::GameTeamInfo& t : b.teams) {
    w.u8(t.team_number);
    w.u8(t.team_colour);
    if (v.goalkeeper) {
      w.u8(t.team_colour);  // the goalkeeper's colour
      w.u8(1);              // the goalkeeper: player 1
    }
    w.u8(t.score);
    w.u8(0);   // penalty shots
    w.u16(0);  // single shots
    if (v.message_budget) w.u16(message_budget);
    for (int p = 0; p < v.max_players; ++p) {
      const bool known = p < al::kGameMaxPlayers;
      // The season's number; one it lacks is refused when the scenario is
      // read, else sent as manual (15), the GameController's catch-all.
      const int code = known ? penaltyCode(v, static_cast<al::Penalty>(t.players[p].penalty)) : 0;
      w.u8(static_cast<std::uint8_t>(code < 0 ? static_cast<int>(al::Penalty::Manual) : code));
      w.u8(known ? t.players[p].secs_till_unpenalised : 0);
    }
  }
  return out;
}

bool decodeReturnData(const PacketVersion& v, const void* bytes, std::size_t size, Return* out, std::string* why) {
  auto no = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  if (size != v.return_bytes)
    return no(std::to_string(size) + " bytes (expected " + std::to_string(v.return_bytes) + ")");
  const auto* p = static_cast<const std::uint8_t*>(bytes);
  if (std::memcmp(p, kReturnHeader, 4) != 0) return no("header is not RGrt");
  if (p[4] != v.return_version)
    return no("version " + std::to_string(p[4]) + " (expected " + std::to_string(v.return_version) + ")");
  *out = Return{};
  if (v.return_version == 4) {  // player, team, fallen, pose, ball age, ball: always "alive"
    out->player = p[5];
    out->team = p[6];
    out->alive = true;
    return true;
  }
  out->team = p[5];
  out->player = p[6];
  if (v.return_version == 3) {
    out->alive = p[7] == 0;  // GAMECONTROLLER_RETURN_MSG_ALIVE (the manual messages went in 2018)
  } else {
    out->alive = p[7] == static_cast<std::uint8_t>(ReturnMessage::Alive);
    out->penalise = p[7] == static_cast<std::uint8_t>(ReturnMessage::ManualPenalise);
    out->unpenalise = p[7] == static_cast<std::uint8_t>(ReturnMessage::ManualUnpenalise);
  }
  return true;
}

}  // namespace simswift::game::spl
