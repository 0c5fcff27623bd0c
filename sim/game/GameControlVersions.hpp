// The GameController's packets as each season's robot programs read them:
// the game data ("RGme") and the return data ("RGrt") of the 2017 season
// (version 10, GameControlPacket.hpp) and of the NAO V6 seasons 2019-2025,
// selected per scenario (`game: {udp: on, version: N}`; docs/game.md).
//
// Facts from the public GameController, github.com/RoboCup-SPL/GameController:
// include/RoboCupGameControlData.h at 13a4731 (February 2019: data 12,
// return 3), 97e52ec (December 2019, the 2020 and 2021 rules: data 13),
// b43e7c6 (January 2022: data 14, return 4) and examples/c/
// RoboCupGameControlData.h at 74da917 (February 2023: data 15), a91c508 (May
// 2024: data 17) and dd76dab (March 2025: data 18); src/data/SPL.java at the
// 2019-2022 commits (5 robots playing). All are little-endian C structs
// without padding. Written here from those facts; each layout is pinned by
// a test against its byte offsets.
//
// What simswift's game state gives each field: state, first half, the
// kicking team, the game phase (the 2017 secondary state has the same
// numbers: normal, penalty shoot-out, overtime, timeout), the clocks, each
// team's number, colour, score and its players' penalties. What it does not
// model is zero: the competition phase and type, the set play, penalty
// shots. From 2022 a team's message budget is the scenario's (its
// GameController's rule); from 2023 a team's goalkeeper is player 1 and its
// goalkeeper wears the field players' colour.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common/libagent/GameState.hpp"

namespace simswift::game::spl {

struct PacketVersion {
  int data_version;          // the RGme struct version a program checks
  const char* seasons;       // SPL seasons that played it
  int max_players;           // player slots per team in the packet
  int players_per_team;      // the packet's playersPerTeam (the seasons' rule)
  bool message_budget;       // TeamInfo carries messageBudget (2022 on)
  bool goalkeeper;           // TeamInfo carries the goalkeeper and its colour (2023 on)
  int return_version;        // the RGrt version robots send back
  std::size_t data_bytes;    // the game data's size
  std::size_t return_bytes;  // the return data's size
};

// Every version simswift sends, oldest first (10: 2017, the default).
const std::vector<PacketVersion>& packetVersions();
// The version with this data version; null if simswift has none.
const PacketVersion* findPacketVersion(int data_version);
// "10 (2017), 12 (2019), ..." for messages.
std::string packetVersionList();

// A penalty (simswift's numbers are the 2017 season's:
// common/libagent/GameState.hpp) as version `v`'s packets number it, or -1
// if that season has no such penalty. The public headers (commits above):
// 2019 (12) numbers 1-8 as 2017 does; from 2020 (13 on) 5 is "illegal
// position" (taken here for 2017's illegal defender, the positioning rule
// it replaced: an assumption), request for pickup moves from 8 to 7, and
// the kick-off goal penalty is gone. Substitute 14 and manual 15 throughout.
int penaltyCode(const PacketVersion& v, common::libagent::Penalty p);

// The game data of version `v` for the game state `b`; message_budget: what
// each team may still send (2022 on).
std::vector<std::uint8_t> encodeGameData(const PacketVersion& v, const common::libagent::GameStateBlock& b,
                                         std::uint8_t packet_number, std::uint16_t message_budget);

// A return packet of version `v` read off a socket: team and player
// numbers and whether it says "alive" (version 4 packets always do; the
// 2017 version also has the manual (un)penalise messages). False (and why)
// unless size, header and version are `v`'s.
struct Return {
  int team = 0, player = 0;
  bool alive = false, penalise = false, unpenalise = false;
};
bool decodeReturnData(const PacketVersion& v, const void* bytes, std::size_t size, Return* out,
                      std::string* why = nullptr);

}  // namespace simswift::game::spl
