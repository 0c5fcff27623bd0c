// The game as the robot knows it (from the GameController's messages, or
// the button interface): state, own penalty, kick-off. Read by localisation
// (initial poses) and behaviour. Units: s.
#pragma once

#include <cstdint>

namespace agent::blackboard {

enum class GameStateId : int32_t { INITIAL = 0, READY, SET, PLAYING, FINISHED };
const char* gameStateName(GameStateId s);

struct GameInfo {
  bool known = false;          // false until a game state arrived: no game (test field)
  GameStateId state = GameStateId::PLAYING;
  bool penalised = false;      // this robot
  double penalty_remaining = 0;  // s
  bool our_kickoff = false;
  int32_t team_number = 0;
  int32_t player_number = 0;
  int64_t changes = 0;         // incremented on every state or penalty change
};

inline const char* gameStateName(GameStateId s) {
  switch (s) {
    case GameStateId::INITIAL: return "INITIAL";
    case GameStateId::READY: return "READY";
    case GameStateId::SET: return "SET";
    case GameStateId::PLAYING: return "PLAYING";
    case GameStateId::FINISHED: return "FINISHED";
  }
  return "?";
}

}  // namespace agent::blackboard
