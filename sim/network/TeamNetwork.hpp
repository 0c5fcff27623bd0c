// The simulator's in-process team network: carries the robots' team packets
// (opaque bytes) to their teammates, as a team's UDP broadcast would, with
// a configured loss rate, delay and per-team packet budget.
//
// - Robot code decides when it sends (agent/comms/TeamSender: 5 Hz); the
//   network does not pace anybody.
// - Budget: packets per team per game (the whole run). A packet sent once the
//   team's budget is spent is dropped (counted as over_budget). 0 = no budget.
// - Loss: each (packet, teammate) pair is lost with probability `loss`,
//   independently (a broadcast can reach one teammate and miss another).
// - Delay: a packet sent at t arrives at t + delay_ms, delivered at the
//   first exchange at or after that time (exchanges run every 10 ms tick, so
//   arrival is rounded up to the tick).
// - Every random draw comes from one generator seeded from the scenario seed
//   and is taken in a fixed order (senders by robot index, their packets in
//   send order, receivers by robot index), so the same seed gives the same
//   deliveries whatever the thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "common/libagent/TeamLink.hpp"

namespace simswift::network {

struct TeamNetworkConfig {
  double loss = 0.0;      // probability 0..1 a packet misses one teammate
  double delay_ms = 0.0;  // ms from send to arrival (>= 0)
  int64_t budget = 0;     // packets per team per game; 0 = unlimited
};

// Which way a packet came and goes: the extension object's team link, or a
// robot's own network (UDP through its wlan0: sim/network/RobotLan.hpp).
enum class Channel : uint8_t { Link, Lan };

struct Delivery {
  int to = -1, from = -1;  // endpoint indices
  Channel channel = Channel::Link;
  int64_t sent_us = 0, arrival_us = 0;
  std::vector<uint8_t> bytes;
};

struct TeamNetworkStats {
  int64_t sent = 0;          // packets accepted from senders (within budget)
  int64_t over_budget = 0;   // packets dropped because the team's budget was spent
  int64_t lost = 0;          // (packet, teammate) pairs dropped by the loss draw
  int64_t delivered = 0;     // (packet, teammate) pairs handed over
  int64_t inbox_overflow = 0;// delivered but the receiver's inbox was full
  int64_t lan_refused = 0;   // Lan deliveries the receiver's network did not take
  int64_t team_sent[2] = {0, 0};
  int64_t team_over_budget[2] = {0, 0};  // of over_budget, per team
};

class TeamNetwork {
 public:
  TeamNetwork(const TeamNetworkConfig& config, uint64_t seed);

  // Endpoints in robot index order. Returns the endpoint index.
  int addEndpoint(int team, int player);
  int numEndpoints() const { return static_cast<int>(endpoints_.size()); }

  // Endpoint `from` sends `bytes` at simulated time `t_us`.
  void send(int from, const uint8_t* bytes, size_t size, int64_t t_us, Channel channel = Channel::Link);
  // Packets due by `t_us`, in arrival order (ties: send order, then receiver).
  std::vector<Delivery> deliver(int64_t t_us);

  // The runner's once-per-tick call: drains every link's outbox (endpoint
  // order, FIFO) as sent at t_us, then writes the packets due by t_us into
  // the receivers' inboxes. links[i] belongs to endpoint i (null: none).
  // Deliveries of Channel::Lan go to `lan` instead, which says whether the
  // receiver's network took it (none: all dropped).
  void exchange(int64_t t_us, const std::vector<common::libagent::TeamLink*>& links,
                const std::function<bool(const Delivery&)>& lan = nullptr);

  // The last exchange's traffic, for observers (the recorder): the packets
  // the robots sent (to = -1, whether or not the budget let them through)
  // and those a receiver's inbox or network took, in exchange order (a
  // packet lost, over the budget, refused or overflowing is not delivered).
  const std::vector<Delivery>& lastSent() const { return last_sent_; }
  const std::vector<Delivery>& lastDelivered() const { return last_delivered_; }

  const TeamNetworkStats& stats() const { return stats_; }
  const TeamNetworkConfig& config() const { return config_; }
  int64_t teamBudgetLeft(int team) const;  // -1 if unlimited
  size_t inFlight() const { return pending_.size(); }

 private:
  struct Endpoint { int team, player; };
  double uniform();  // [0, 1), 53 bits, same on every platform

  TeamNetworkConfig config_;
  int64_t delay_us_;
  std::mt19937_64 rng_;
  std::vector<Endpoint> endpoints_;
  // (arrival_us, sequence) -> delivery: ordered, deterministic.
  std::map<std::pair<int64_t, uint64_t>, Delivery> pending_;
  uint64_t sequence_ = 0;
  TeamNetworkStats stats_;
  std::vector<Delivery> last_sent_, last_delivered_;
};

}  // namespace simswift::network
