// Robot code: the game-state extension object -> the plain GameState section
// Behaviour reads (later wrapped as a module by the Blackboard framework).
#pragma once

#include <cstdint>

#include "agent/libagent/GameState.hpp"

namespace agent::comms {

struct GameState {
  bool valid = false;  // false until the block has been written once
  agent::libagent::GameStateValue state = agent::libagent::GameStateValue::Initial;
  agent::libagent::SecondaryState secondary = agent::libagent::SecondaryState::Normal;
  bool penalised = false;                 // this robot
  agent::libagent::Penalty penalty = agent::libagent::Penalty::None;
  int secs_till_unpenalised = 0;          // s
  int secs_remaining = 0;                 // s in the half
  int kickoff_team = -1;                  // SPL team number, -1 drop ball / unknown
  bool our_kickoff = false;
  bool first_half = true;
  int our_score = 0, their_score = 0;
  int64_t sim_time_us = 0;                // when the simulator wrote it

  // The robot may move: PLAYING (or READY) and not penalised.
  bool mayMove() const {
    return valid && !penalised &&
           (state == agent::libagent::GameStateValue::Playing || state == agent::libagent::GameStateValue::Ready);
  }
};

class GameStateReader {
 public:
  // team: this robot's SPL team number (found in the block's teams[], as a
  // robot finds itself in the GameController's packet); player 1..
  GameStateReader(int team, int player) : team_(team), player_(player) {}
  // A copy of `block` is taken first, so a half-written block cannot mix two
  // states (the simulator writes between ticks anyway). Null or a bad magic
  // gives an invalid GameState (INITIAL: the robot stands).
  GameState read(const agent::libagent::GameStateBlock* block) const;

 private:
  int team_, player_;
};

}  // namespace agent::comms
