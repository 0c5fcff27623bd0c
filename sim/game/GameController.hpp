// The simulator's GameController: plays the SPL GameController for a run.
// A scenario gives a timeline of game states and timed penalties; update()
// advances them in simulated time and fill() writes what a robot would be
// told into its GameStateBlock (common/libagent/GameState.hpp).
//
// Clock rules (as the GameController does): the half's seconds remaining
// count down only while PLAYING; READY shows a 45 s secondary countdown.
// A penalty lasts `duration` s (its timer counts down in every state); a
// negative duration means until a later `penalty: none` entry for that robot.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/libagent/GameState.hpp"
#include "sim/game/GameControllerUdp.hpp"

namespace simswift::game {

using common::libagent::GameStateValue;
using common::libagent::Penalty;
using common::libagent::SecondaryState;

struct GameConfig {
  struct StateChange {
    double t_s = 0;                         // s of simulated time
    GameStateValue state = GameStateValue::Playing;
    SecondaryState secondary = SecondaryState::Normal;
    int kickoff_team = -1;                  // -1: unchanged; 0/1 team index; 255 drop ball
  };
  struct PenaltyEvent {
    double t_s = 0;           // s
    int robot = 0;            // scenario robot index
    Penalty penalty = Penalty::RequestForPickup;  // None: unpenalise now
    double duration_s = 30;   // s; < 0 = until a later penalty: none
  };
  // With no `game:` block robots play from the start (no game controller).
  GameStateValue initial_state = GameStateValue::Playing;
  int kickoff_team = 0;
  double half_duration_s = 600;   // s (SPL: 10 min halves)
  bool first_half = true;
  // Where an unpenalised robot goes: back to where it was taken from
  // (Return::Previous) or it stays on the sideline (Return::Sideline, as
  // SPL robots re-enter the field).
  enum class Return { Previous, Sideline } on_unpenalise = Return::Previous;
  std::vector<StateChange> timeline;     // sorted by t_s
  std::vector<PenaltyEvent> penalties;   // sorted by t_s
  // The SPL GameController's UDP packets besides the extension block
  // (off by default; sim/game/GameControllerUdp.hpp).
  GameUdpConfig udp;
};

struct GameEvent {
  enum class Kind { Penalised, Unpenalised } kind;
  int robot;
  Penalty penalty;
};

class GameController {
 public:
  // team: the side index (0 = blue, 1 = red: the order of teams[] in the
  // game state block); team_number: the SPL team number (-1 = same as team).
  struct RobotId { int team, player, team_number = -1; };
  GameController(GameConfig config, std::vector<RobotId> robots);

  // Advances to simulated time t_us (monotonic; call once per tick). Returns
  // the robots penalised / unpenalised by this call, in a fixed order.
  std::vector<GameEvent> update(int64_t t_us);
  // Writes the current game state into `b` (also magic and update count).
  void fill(common::libagent::GameStateBlock& b) const;

  GameStateValue state() const { return state_; }
  SecondaryState secondary() const { return secondary_; }
  int kickoffTeam() const { return kickoff_team_; }  // side index (0/1), 255 drop ball
  int teamNumber(int side) const;                     // SPL team number playing on `side`
  double secsRemaining() const;                 // s, fractional
  bool penalised(int robot) const { return robots_.at(robot).penalty != Penalty::None; }
  Penalty penalty(int robot) const { return robots_.at(robot).penalty; }
  double secsTillUnpenalised(int robot) const;  // s, fractional; 0 if not penalised or open-ended
  const GameConfig& config() const { return config_; }

 private:
  struct RobotState {
    RobotId id;
    Penalty penalty = Penalty::None;
    int64_t until_us = -1;  // -1: open-ended
  };
  GameConfig config_;
  std::vector<RobotState> robots_;
  GameStateValue state_;
  SecondaryState secondary_ = SecondaryState::Normal;
  int kickoff_team_;
  int64_t now_us_ = -1;
  int64_t played_us_ = 0;        // time spent PLAYING this half
  int64_t state_since_us_ = 0;   // when the current state began
  size_t next_change_ = 0, next_penalty_ = 0;
  uint32_t updates_ = 0;
};

const char* stateName(GameStateValue s);
const char* penaltyName(Penalty p);
// Parsers for scenario names ("playing", "request_for_pickup"); false if unknown.
bool parseState(const std::string& name, GameStateValue* out);
bool parsePenalty(const std::string& name, Penalty* out);
std::vector<std::string> stateNames();
std::vector<std::string> penaltyNames();

}  // namespace simswift::game
