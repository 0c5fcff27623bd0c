// Robot code: the game-state extension object -> the plain GameState section
// Behaviour reads (later wrapped as a module by the Blackboard framework).
#pragma once

#include <cstdint>

#include "common/libagent/GameState.hpp"

namespace agent::comms {

struct GameState {
  bool valid = false;  // false until the block has been written once
  common::libagent::GameStateValue state = common::libagent::GameStateValue::Initial;
  common::libagent::SecondaryState secondary = common::libagent::SecondaryState::Normal;
  bool penalised = false;                 // this robot
  common::libagent::Penalty penalty = common::libagent::Penalty::None;
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
           (state == common::libagent::GameStateValue::Playing || state == common::libagent::GameStateValue::Ready);
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
  GameState read(const common::libagent::GameStateBlock* block) const;

 private:
  int team_, player_;
};

}  // namespace agent::comms
