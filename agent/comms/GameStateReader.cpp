#include "agent/comms/GameStateReader.hpp"

namespace agent::comms {

namespace al = common::libagent;

GameState GameStateReader::read(const al::GameStateBlock* block) const {
  GameState g;
  if (!block) return g;
  const al::GameStateBlock b = *block;
  if (b.magic != al::kGameStateMagic || b.updates == 0) return g;
  if (player_ < 1 || player_ > al::kGameMaxPlayers) return g;
  int side = -1;  // which of teams[] is ours
  for (int t = 0; t < 2; ++t)
    if (b.teams[t].team_number == team_) side = t;
  if (side < 0) return g;
  g.valid = true;
  g.state = b.state <= static_cast<uint8_t>(al::GameStateValue::Finished) ? static_cast<al::GameStateValue>(b.state)
                                                                          : al::GameStateValue::Initial;
  g.secondary = b.secondary_state <= static_cast<uint8_t>(al::SecondaryState::Timeout)
                    ? static_cast<al::SecondaryState>(b.secondary_state)
                    : al::SecondaryState::Normal;
  const al::GamePlayerInfo& me = b.teams[side].players[player_ - 1];
  g.penalty = static_cast<al::Penalty>(me.penalty);
  g.penalised = me.penalty != 0;
  g.secs_till_unpenalised = me.secs_till_unpenalised;
  g.secs_remaining = b.secs_remaining;
  g.kickoff_team = b.kickoff_team == 255 ? -1 : b.kickoff_team;
  g.our_kickoff = g.kickoff_team == team_;
  g.first_half = b.first_half != 0;
  g.our_score = b.teams[side].score;
  g.their_score = b.teams[1 - side].score;
  g.sim_time_us = b.sim_time_us;
  return g;
}

}  // namespace agent::comms
