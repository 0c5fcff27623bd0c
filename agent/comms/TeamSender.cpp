#include "agent/comms/TeamSender.hpp"

#include <cmath>
#include <stdexcept>

namespace agent::comms {

TeamSender::TeamSender(int team, int player, double rate_hz)
    : team_(team), player_(player), period_us_(static_cast<int64_t>(std::llround(1e6 / rate_hz))) {
  if (!(rate_hz > 0)) throw std::invalid_argument("TeamSender: rate_hz must be > 0");
}

bool TeamSender::maybeSend(TeamTransport& transport, int64_t now_us, const SplMessage& content) {
  if (!due(now_us)) return false;
  SplMessage m = content;
  m.team = team_;
  m.player = player_;
  // Counted as sent attempt either way: the next try waits a period, as a
  // UDP send that failed would not be retried at once either.
  last_sent_us_ = now_us;
  tried_ = true;
  if (!transport.send(serialise(m))) {
    ++failed_;
    return false;
  }
  ++sent_;
  return true;
}

}  // namespace agent::comms
