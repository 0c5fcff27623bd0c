// The SPL GameController's UDP packets of the 2017 season, byte for byte:
// the game data ("RGme", struct version 10) the GameController sends to
// the robots' port 3838 every 500 ms, and the return data ("RGrt", version 2)
// a robot may send to the GameController's port 3939.
//
// Facts (fields, sizes, units, constants) from the public GameController
// source, github.com/RoboCup-SPL/GameController at its April 2017 state
// (commit ebe1341): include/RoboCupGameControlData.h, SPLCoachMessage.h
// (coach message 253 bytes), src/data/GameControlData.java and TeamInfo.java
// (little-endian ByteBuffers, no padding: 588 and 284 bytes), SPL.java
// (6 players per team: 5 + a substitute) and controller/net/Sender.java
// (a packet every 500 ms). Written here from those facts; the layout is
// pinned by the static_asserts below.
//
// The packet carries what GameController::fill() writes into the
// game-state extension block (common/libagent/GameState.hpp): one home for
// the game's state, two ways for a robot to read it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "common/libagent/GameState.hpp"

namespace simswift::game::spl {

constexpr int kDataPort = 3838;    // robots listen here for game data
constexpr int kReturnPort = 3939;  // the GameController listens here for return data
constexpr char kDataHeader[4] = {'R', 'G', 'm', 'e'};
constexpr uint16_t kDataVersion = 10;
constexpr char kReturnHeader[4] = {'R', 'G', 'r', 't'};
constexpr uint8_t kReturnVersion = 2;
constexpr int kMaxPlayers = 11;          // player slots per team in the packet
constexpr int kCoachMessageBytes = 253;  // SPL coach message, 2017
constexpr uint8_t kPlayersPerTeam = 6;   // SPL 2017: 5 players + 1 substitute
constexpr uint8_t kDropBall = 255;       // kickoff_team when no team kicks off
constexpr uint8_t kGameRoundRobin = 0;   // game_type
constexpr uint16_t kNoDropIn = 0xFFFF;   // drop_in_time before the first drop-in
constexpr int64_t kSendIntervalUs = 500000;  // us between packets (the GameController's rate)

// Return messages (RoboCupGameControlReturnData::message).
enum class ReturnMessage : uint8_t { ManualPenalise = 0, ManualUnpenalise = 1, Alive = 2 };

struct PlayerInfo {
  uint8_t penalty;                // SPL penalty number (common::libagent::Penalty)
  uint8_t secs_till_unpenalised;  // s
};

struct TeamInfo {
  uint8_t team_number;   // SPL team number
  uint8_t team_colour;   // 0 blue, 1 red, ... (GameController colours)
  uint8_t score;
  uint8_t penalty_shot;  // penalty shots taken
  uint16_t single_shots; // bit i: shot i scored
  uint8_t coach_sequence;
  uint8_t coach_message[kCoachMessageBytes];
  PlayerInfo coach;
  PlayerInfo players[kMaxPlayers];  // [player number - 1]
};

struct GameControlData {
  char header[4];             // kDataHeader
  uint16_t version;           // kDataVersion
  uint8_t packet_number;      // +1 per packet sent, wrapping at 256
  uint8_t players_per_team;
  uint8_t game_type;          // 0 round robin, 1 play-off, 2/3 mixed team
  uint8_t state;              // common::libagent::GameStateValue
  uint8_t first_half;         // 1 = first half
  uint8_t kickoff_team;       // SPL team number with the kick-off, or kDropBall
  uint8_t secondary_state;    // common::libagent::SecondaryState
  uint8_t drop_in_team;       // team colour that caused the last drop-in
  uint16_t drop_in_time;      // s since the last drop-in (kNoDropIn: none yet)
  uint16_t secs_remaining;    // s left in the half
  uint16_t secondary_time;    // s shown as secondary time (READY's countdown, ...)
  TeamInfo teams[2];          // teams[0] is the blue side in simswift
};

struct ReturnData {
  char header[4];   // kReturnHeader
  uint8_t version;  // kReturnVersion
  uint8_t team;     // SPL team number
  uint8_t player;   // player number, from 1
  uint8_t message;  // ReturnMessage
};

// The wire layout (little-endian, no padding), as the GameController packs it.
#if defined(__BYTE_ORDER__) && defined(__ORDER_LITTLE_ENDIAN__)
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the packets are little-endian, copied as is");
#endif
static_assert(sizeof(PlayerInfo) == 2);
static_assert(sizeof(TeamInfo) == 284);
static_assert(offsetof(TeamInfo, single_shots) == 4);
static_assert(offsetof(TeamInfo, coach_sequence) == 6);
static_assert(offsetof(TeamInfo, coach_message) == 7);
static_assert(offsetof(TeamInfo, coach) == 260);
static_assert(offsetof(TeamInfo, players) == 262);
static_assert(sizeof(GameControlData) == 588);
static_assert(offsetof(GameControlData, version) == 4);
static_assert(offsetof(GameControlData, packet_number) == 6);
static_assert(offsetof(GameControlData, state) == 9);
static_assert(offsetof(GameControlData, kickoff_team) == 11);
static_assert(offsetof(GameControlData, secondary_state) == 12);
static_assert(offsetof(GameControlData, drop_in_team) == 13);
static_assert(offsetof(GameControlData, drop_in_time) == 14);
static_assert(offsetof(GameControlData, secs_remaining) == 16);
static_assert(offsetof(GameControlData, secondary_time) == 18);
static_assert(offsetof(GameControlData, teams) == 20);
static_assert(sizeof(ReturnData) == 8);
static_assert(offsetof(ReturnData, message) == 7);

// The packet for the game state `b` (GameController::fill's block); the
// fields simswift does not model (score, penalty shots, coach, drop-in) are
// zero / "none".
GameControlData encode(const common::libagent::GameStateBlock& b, uint8_t packet_number);
ReturnData makeReturn(uint8_t team, uint8_t player, ReturnMessage message);

// Decoders for bytes off a socket: false (and why, if asked) unless the
// size, header and version are the 2017 ones.
bool decode(const void* bytes, size_t size, GameControlData* out, std::string* why = nullptr);
bool decodeReturn(const void* bytes, size_t size, ReturnData* out, std::string* why = nullptr);

}  // namespace simswift::game::spl
