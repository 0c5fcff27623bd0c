#include "agent/comms/TeamTransport.hpp"

#include "agent/comms/SplMessage.hpp"

namespace agent::comms {

static_assert(kSplMaxPacketBytes == common::libagent::kMaxTeamPacketBytes,
              "the team link's slots hold one SPL standard message");

bool TeamLinkTransport::send(const std::vector<uint8_t>& bytes) {
  if (!link_) return false;
  return link_->outbox.push(bytes.data(), bytes.size(), 0);
}

std::vector<ReceivedPacket> TeamLinkTransport::receive() {
  std::vector<ReceivedPacket> out;
  if (!link_) return out;
  common::libagent::TeamPacket p;
  while (link_->inbox.pop(p)) out.push_back({std::vector<uint8_t>(p.bytes, p.bytes + p.size), p.time_us});
  return out;
}

}  // namespace agent::comms
