#include "sim/network/TeamNetwork.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/random/DeriveSeed.hpp"

namespace simswift::network {

namespace al = common::libagent;

TeamNetwork::TeamNetwork(const TeamNetworkConfig& config, uint64_t seed)
    : config_(config),
      delay_us_(static_cast<int64_t>(std::llround(config.delay_ms * 1000.0))),
      // Its own stream: the network's draws never shift another seeded source.
      rng_(common::random::deriveSeed(seed, common::random::seed_tag::kTeamNetwork)) {
  if (!(config.loss >= 0 && config.loss <= 1)) throw std::invalid_argument("team network: loss must be 0..1");
  if (!(config.delay_ms >= 0)) throw std::invalid_argument("team network: delay_ms must be >= 0");
  if (config.budget < 0) throw std::invalid_argument("team network: budget must be >= 0");
}

int TeamNetwork::addEndpoint(int team, int player) {
  if (team < 0 || team > 1) throw std::invalid_argument("team network: team " + std::to_string(team));
  endpoints_.push_back({team, player});
  return static_cast<int>(endpoints_.size()) - 1;
}

double TeamNetwork::uniform() { return static_cast<double>(rng_() >> 11) * (1.0 / 9007199254740992.0); }

int64_t TeamNetwork::teamBudgetLeft(int team) const {
  if (config_.budget == 0) return -1;
  return std::max<int64_t>(0, config_.budget - stats_.team_sent[team]);
}

void TeamNetwork::send(int from, const uint8_t* bytes, size_t size, int64_t t_us, Channel channel) {
  const Endpoint& src = endpoints_.at(from);
  // The tick's traffic for observers (lastSent), over the budget or not,
  // from the block's outbox or a robot's own network: a new tick, a new list.
  if (!last_sent_.empty() && last_sent_.back().sent_us != t_us) last_sent_.clear();
  last_sent_.push_back({-1, from, channel, t_us, t_us, std::vector<uint8_t>(bytes, bytes + size)});
  if (config_.budget > 0 && stats_.team_sent[src.team] >= config_.budget) {
    ++stats_.over_budget;
    ++stats_.team_over_budget[src.team];
    return;
  }
  ++stats_.sent;
  ++stats_.team_sent[src.team];
  for (int to = 0; to < numEndpoints(); ++to) {
    if (to == from || endpoints_[to].team != src.team) continue;
    // Always draw, even with loss 0 or 1, so changing the rate does not
    // shift which later draws belong to which pair.
    const bool lost = uniform() < config_.loss;
    if (lost) {
      ++stats_.lost;
      continue;
    }
    Delivery d;
    d.to = to;
    d.from = from;
    d.channel = channel;
    d.sent_us = t_us;
    d.arrival_us = t_us + delay_us_;
    d.bytes.assign(bytes, bytes + size);
    pending_.emplace(std::make_pair(d.arrival_us, sequence_++), std::move(d));
  }
}

std::vector<Delivery> TeamNetwork::deliver(int64_t t_us) {
  std::vector<Delivery> out;
  auto it = pending_.begin();
  while (it != pending_.end() && it->first.first <= t_us) {
    out.push_back(std::move(it->second));
    it = pending_.erase(it);
  }
  stats_.delivered += static_cast<int64_t>(out.size());
  return out;
}

void TeamNetwork::exchange(int64_t t_us, const std::vector<al::TeamLink*>& links,
                           const std::function<bool(const Delivery&)>& lan) {
  al::TeamPacket p;
  if (!last_sent_.empty() && last_sent_.back().sent_us != t_us) last_sent_.clear();  // none sent this tick
  last_delivered_.clear();
  for (int i = 0; i < numEndpoints() && i < static_cast<int>(links.size()); ++i) {
    if (!links[i]) continue;
    // At most a full ring per tick: a program that writes the ring's head
    // (shared memory) cannot keep the simulator draining.
    for (uint32_t n = 0; n < al::kOutboxSlots && links[i]->outbox.pop(p); ++n) send(i, p.bytes, p.size, t_us);
  }
  for (Delivery& d : deliver(t_us)) {
    if (d.channel == Channel::Lan) {
      if (lan && lan(d))
        last_delivered_.push_back(std::move(d));
      else
        ++stats_.lan_refused;
      continue;
    }
    al::TeamLink* link = d.to < static_cast<int>(links.size()) ? links[d.to] : nullptr;
    if (!link || !link->inbox.push(d.bytes.data(), d.bytes.size(), t_us, endpoints_[d.from].player))
      ++stats_.inbox_overflow;
    else
      last_delivered_.push_back(std::move(d));
  }
}

}  // namespace simswift::network
