// simswift's team-communication extension object, beside the libagent block
// (never inside it): per robot an outbox the robot code writes packets into
// and an inbox the simulator's network fills with teammates' packets.
//
// Each ring has one producer and one consumer (outbox: robot code -> the
// simulator; inbox: the simulator -> robot code), so indices are atomics and
// no lock is needed. Determinism does not rest on the atomics but on when the
// simulator touches the rings: only at the end of a tick, after every robot
// thread has answered (its joint command / perception_done) and before the next tick
// is posted (Runner::tick() step 7), so the robot code always sees the same
// packets at the same simulated time. On a real robot a UDP socket replaces
// this object (see agent/comms/TeamTransport.hpp).
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>

namespace common::libagent {

constexpr size_t kMaxTeamPacketBytes = 852;  // the SPL standard message (v6) C struct
constexpr uint32_t kTeamLinkMagic = 0x53575454;  // "SWTT"

struct TeamPacket {
  int64_t time_us;                       // outbox: when queued; inbox: when delivered (simulated)
  int32_t from_player;                   // inbox: sender's player number (simulator's knowledge; 0 in outbox)
  uint32_t size;                         // bytes used
  uint8_t bytes[kMaxTeamPacketBytes];
};

// Single-producer single-consumer ring of N packets.
template <uint32_t N>
struct PacketRing {
  std::atomic<uint32_t> head{0};      // next slot the producer writes (monotonic)
  std::atomic<uint32_t> tail{0};      // next slot the consumer reads (monotonic)
  std::atomic<uint32_t> overflows{0}; // packets the producer found no room for (dropped)
  TeamPacket slots[N];

  // Producer. False (and counted) if full or `size` too large.
  bool push(const uint8_t* bytes, size_t size, int64_t time_us, int32_t from_player = 0) {
    const uint32_t h = head.load(std::memory_order_relaxed);
    if (size > kMaxTeamPacketBytes || h - tail.load(std::memory_order_acquire) >= N) {
      overflows.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    TeamPacket& p = slots[h % N];
    p.time_us = time_us;
    p.from_player = from_player;
    p.size = static_cast<uint32_t>(size);
    if (size) std::memcpy(p.bytes, bytes, size);
    head.store(h + 1, std::memory_order_release);
    return true;
  }
  // Consumer. False if empty.
  bool pop(TeamPacket& out) {
    const uint32_t t = tail.load(std::memory_order_relaxed);
    if (t == head.load(std::memory_order_acquire)) return false;
    const TeamPacket& p = slots[t % N];
    out.time_us = p.time_us;
    out.from_player = p.from_player;
    // The other process may rewrite the size at any time: read it once,
    // then check and use that value (never trust shared memory).
    const uint32_t size = p.size;
    out.size = size <= kMaxTeamPacketBytes ? size : kMaxTeamPacketBytes;
    std::memcpy(out.bytes, p.bytes, out.size);
    tail.store(t + 1, std::memory_order_release);
    return true;
  }
  uint32_t size() const { return head.load() - tail.load(); }
};

// The robot code sends at 5 Hz and the simulator drains every 10 ms, so a
// few outbox slots are plenty; the inbox holds what arrives between two
// reads at 30 Hz from up to five teammates (more is counted as overflow).
constexpr uint32_t kOutboxSlots = 4;
constexpr uint32_t kInboxSlots = 32;

struct TeamLink {
  uint32_t magic = kTeamLinkMagic;
  PacketRing<kOutboxSlots> outbox;  // robot code -> network
  PacketRing<kInboxSlots> inbox;    // network -> robot code
};

}  // namespace common::libagent
