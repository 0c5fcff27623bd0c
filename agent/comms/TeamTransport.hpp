// How robot code sends and receives team packets, whatever carries them: in
// simulation the simulator's network behind the TeamLink extension object
// (TeamLinkTransport), on a real robot a UDP broadcast socket (same
// interface, not written here). Packets are opaque bytes to the transport;
// agent/comms/SplMessage parses them.
#pragma once

#include <cstdint>
#include <vector>

#include "agent/blackboard/Extensions.hpp"
#include "common/libagent/TeamLink.hpp"

namespace agent::comms {

// Bytes and arrival time: the representation the team inbox section holds.
using ReceivedPacket = blackboard::ReceivedTeamPacket;

class TeamTransport {
 public:
  virtual ~TeamTransport() = default;
  // Queues one packet for the team. False if it could not be queued.
  virtual bool send(const std::vector<uint8_t>& bytes) = 0;
  // Every packet that arrived since the last call, in arrival order.
  virtual std::vector<ReceivedPacket> receive() = 0;
};

// The simulator's transport: writes the outbox, drains the inbox of one
// robot's TeamLink (see TeamLink.hpp for when the simulator touches them).
class TeamLinkTransport : public TeamTransport {
 public:
  explicit TeamLinkTransport(common::libagent::TeamLink* link) : link_(link) {}
  bool send(const std::vector<uint8_t>& bytes) override;
  std::vector<ReceivedPacket> receive() override;

 private:
  common::libagent::TeamLink* link_;
};

// In-memory loopback for tests: what is sent is kept; receive() returns what
// was injected with deliver().
class MemoryTransport : public TeamTransport {
 public:
  bool send(const std::vector<uint8_t>& bytes) override {
    sent.push_back(bytes);
    return true;
  }
  std::vector<ReceivedPacket> receive() override {
    std::vector<ReceivedPacket> out;
    out.swap(pending);
    return out;
  }
  void deliver(std::vector<uint8_t> bytes, int64_t time_us = 0) { pending.push_back({std::move(bytes), time_us}); }
  std::vector<std::vector<uint8_t>> sent;
  std::vector<ReceivedPacket> pending;
};

}  // namespace agent::comms
