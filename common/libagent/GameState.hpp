// simswift's game-state extension object, beside the libagent block (never
// inside it): what a GameController would tell the robot, laid out in the
// spirit of the SPL GameController's RoboCupGameControlData (state,
// secondary state, kick-off team, seconds remaining, per team and player the
// penalty and seconds until unpenalised). The simulator's GameController
// (sim/game) writes it at the end of a tick (Runner::tick() step 7) while no
// robot thread runs; the robot code reads it (agent/comms/GameStateReader).
//
// Units: seconds; team numbers are simswift's team indices (0, 1); players
// are indexed by player number - 1.
#pragma once

#include <cstdint>

namespace common::libagent {

// Values as in the GameController's data.
enum class GameStateValue : uint8_t { Initial = 0, Ready = 1, Set = 2, Playing = 3, Finished = 4 };
enum class SecondaryState : uint8_t { Normal = 0, PenaltyShoot = 1, Overtime = 2, Timeout = 3 };
// SPL penalty numbers (GameController data of the 2016-2018 seasons).
enum class Penalty : uint8_t {
  None = 0,
  IllegalBallContact = 1,
  PlayerPushing = 2,
  IllegalMotionInSet = 3,
  InactivePlayer = 4,
  IllegalDefender = 5,
  LeavingTheField = 6,
  KickOffGoal = 7,
  RequestForPickup = 8,
  Substitute = 14,
  Manual = 15,
};

constexpr uint32_t kGameStateMagic = 0x53574753;  // "SWGS"
constexpr int kGameMaxPlayers = 6;                // player numbers 1..6

struct GamePlayerInfo {
  uint8_t penalty;                // Penalty
  uint8_t secs_till_unpenalised;  // s, rounded up; 0 when not penalised
};

struct GameTeamInfo {
  uint8_t team_number;  // SPL team number
  uint8_t team_colour;  // 0 blue, 1 red (GameController colours)
  uint8_t score;
  uint8_t reserved;
  GamePlayerInfo players[kGameMaxPlayers];  // [player number - 1]
};

struct GameStateBlock {
  uint32_t magic;
  uint32_t updates;          // incremented at every write (0 = never written)
  int64_t sim_time_us;       // simulated time of the last write
  uint8_t state;             // GameStateValue
  uint8_t secondary_state;   // SecondaryState
  uint8_t first_half;        // 1 = first half
  uint8_t kickoff_team;      // SPL team number with the kick-off (255 = drop ball)
  uint16_t secs_remaining;   // s left in the half (counts down while PLAYING)
  uint16_t secondary_time;   // s shown as secondary time (e.g. READY's 45 s)
  GameTeamInfo teams[2];     // by team index
};

}  // namespace common::libagent
