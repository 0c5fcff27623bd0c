#include "agent/comms/TeamSender.hpp"

#include <cmath>
#include <stdexcept>

namespace agent::comms {

TeamSender::TeamSender(int team, int player, double rate_hz)
    : team_(team), player_(player), period_us_(static_cast<int64_t>(std::llround(1e6 / rate_hz))) {
  if (!(rate_hz > 0)) throw std::invalid_argument("TeamSender: rate_hz must be > 0");
}

std::vector<uint8_t> TeamSender::nextPacket(int64_t now_us, const SplMessage& content) {
  if (!due(now_us)) return {};
  SplMessage m = content;
  m.team = team_;
  m.player = player_;
  // An attempt either way: the next try waits a period, as a UDP send that
  // failed would not be retried at once either.
  last_sent_us_ = now_us;
  tried_ = true;
  return serialise(m);
}

bool TeamSender::maybeSend(TeamTransport& transport, int64_t now_us, const SplMessage& content) {
  const std::vector<uint8_t> bytes = nextPacket(now_us, content);
  if (bytes.empty()) return false;
  const bool accepted = transport.send(bytes);
  recordSend(accepted);
  return accepted;
}

}  // namespace agent::comms
