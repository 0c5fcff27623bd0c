// Robot code: turns the packets that arrived into per-teammate state.
// Malformed packets (SplMessage parse errors) are counted and dropped;
// packets of another team or with our own player number are ignored (counted).
// Later wrapped as a module (team receive) by the Blackboard framework.
#pragma once

#include <array>
#include <cstdint>
#include <limits>

#include "agent/comms/SplMessage.hpp"
#include "agent/comms/TeamTransport.hpp"

namespace agent::comms {

struct TeammateState {
  bool heard = false;        // at least one valid packet so far
  int64_t last_heard_us = 0; // simulated time of the latest packet (arrival, else the update's time)
  int64_t packets = 0;       // valid packets from this teammate
  SplMessage last;           // the latest message (units as SplMessage)
};

struct TeamReceiverStats {
  int64_t received = 0;      // every packet taken from the transport
  int64_t accepted = 0;
  int64_t malformed = 0;     // failed to parse: dropped
  int64_t other_team = 0;    // valid, but not our team number: ignored
  int64_t own = 0;           // valid, our own player number: ignored
  ParseError last_error = ParseError::None;
};

class TeamReceiver {
 public:
  TeamReceiver(int team, int player) : team_(team), player_(player) {}

  // Takes everything the transport holds. `now_us`: the robot's simulated time.
  void update(TeamTransport& transport, int64_t now_us);
  // Same, for packets already taken from a transport.
  void receive(const std::vector<ReceivedPacket>& packets, int64_t now_us);

  // Teammate by player number 1..kSplMaxPlayers.
  const TeammateState& teammate(int player) const { return mates_.at(player - 1); }
  // s since teammate `player` was last heard at `now_us`; infinity if never.
  double secondsSinceHeard(int player, int64_t now_us) const;
  const TeamReceiverStats& stats() const { return stats_; }
  int team() const { return team_; }
  int player() const { return player_; }

 private:
  int team_, player_;
  std::array<TeammateState, kSplMaxPlayers> mates_{};
  TeamReceiverStats stats_;
};

}  // namespace agent::comms
