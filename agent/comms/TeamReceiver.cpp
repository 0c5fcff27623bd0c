#include "agent/comms/TeamReceiver.hpp"

namespace agent::comms {

void TeamReceiver::update(TeamTransport& transport, int64_t now_us) { receive(transport.receive(), now_us); }

void TeamReceiver::receive(const std::vector<ReceivedPacket>& packets, int64_t now_us) {
  for (const ReceivedPacket& p : packets) {
    ++stats_.received;
    ParseResult r = parse(p.bytes);
    if (!r.ok()) {
      ++stats_.malformed;
      stats_.last_error = r.error;
      continue;
    }
    if (r.message.team != team_) {
      ++stats_.other_team;
      continue;
    }
    if (r.message.player == player_) {
      ++stats_.own;
      continue;
    }
    ++stats_.accepted;
    TeammateState& m = mates_[r.message.player - 1];  // parse() checked 1..kSplMaxPlayers
    m.heard = true;
    m.last_heard_us = p.time_us > 0 ? p.time_us : now_us;
    ++m.packets;
    m.last = std::move(r.message);
  }
}

double TeamReceiver::secondsSinceHeard(int player, int64_t now_us) const {
  const TeammateState& m = teammate(player);
  if (!m.heard) return std::numeric_limits<double>::infinity();
  return (now_us - m.last_heard_us) * 1e-6;
}

}  // namespace agent::comms
