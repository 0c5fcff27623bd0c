// The simulator's team network: loss at the configured rate, delay by the
// configured time, the per-team budget, team isolation and seeded
// determinism, through the same TeamLink rings the robot code uses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <tuple>

#include "agent/comms/SplMessage.hpp"
#include "agent/comms/TeamTransport.hpp"
#include "sim/network/TeamNetwork.hpp"

using namespace simswift::network;
namespace al = common::libagent;
namespace ac = agent::comms;

namespace {

struct Robot { int team, player; };

// The send time the harness puts in the free data area (8 bytes, little-endian us).
int64_t sentTime(const ac::SplMessage& m) {
  int64_t t = 0;
  for (int b = 0; b < 8; ++b) t |= static_cast<int64_t>(m.data.at(b)) << (8 * b);
  return t;
}

// Robots in robot-index order, each with a TeamLink; every robot sends one
// packet every `period_ticks` (offset by its index) and reads its inbox
// every tick, as the runner's step 7 and the Perception thread would.
struct Harness {
  TeamNetwork net;
  std::vector<std::unique_ptr<al::TeamLink>> links;
  std::vector<al::TeamLink*> ptrs;
  std::vector<Robot> robots;
  // Per received packet: receiver, sender player, sent (from the payload), arrival.
  std::vector<std::tuple<int, int, int64_t, int64_t>> got;
  std::vector<int> teams_seen;  // 0 if a packet reached a robot of its own team, else 1

  Harness(const TeamNetworkConfig& c, uint64_t seed, std::vector<Robot> rs) : net(c, seed), robots(std::move(rs)) {
    for (const Robot& r : robots) {
      net.addEndpoint(r.team, r.player);
      links.push_back(std::make_unique<al::TeamLink>());
      ptrs.push_back(links.back().get());
    }
  }
  void run(int ticks, int period_ticks = 20, bool read = true) {
    for (int k = 1; k <= ticks; ++k) {
      const int64_t t_us = int64_t(k) * 10000;
      for (size_t i = 0; i < robots.size(); ++i) {
        if ((k + static_cast<int>(i)) % period_ticks != 0) continue;
        ac::SplMessage m;
        m.team = robots[i].team;
        m.player = robots[i].player;
        for (int b = 0; b < 8; ++b) m.data.push_back(static_cast<uint8_t>(t_us >> (8 * b)));  // send time
        ac::TeamLinkTransport(ptrs[i]).send(ac::serialise(m));
      }
      net.exchange(t_us, ptrs);
      if (!read) continue;
      for (size_t i = 0; i < robots.size(); ++i)
        for (const ac::ReceivedPacket& p : ac::TeamLinkTransport(ptrs[i]).receive()) {
          const ac::ParseResult r = ac::parse(p.bytes);
          ASSERT_TRUE(r.ok());
          teams_seen.push_back(r.message.team == robots[i].team ? 0 : 1);
          got.emplace_back(static_cast<int>(i), r.message.player, sentTime(r.message), p.time_us);
        }
    }
  }
};

const std::vector<Robot> kTwoTeams = {{0, 1}, {0, 2}, {0, 3}, {1, 1}, {1, 2}};

}  // namespace

TEST(TeamNetwork, DeliversToTeammatesOnlyWithoutLossOrDelay) {
  Harness h({}, 1, kTwoTeams);
  h.run(1000);  // 10 s, 5 Hz each
  const TeamNetworkStats& s = h.net.stats();
  EXPECT_EQ(s.sent, 5 * 50);
  // Team 0: 3 robots x 2 teammates; team 1: 2 robots x 1 teammate.
  EXPECT_EQ(s.delivered, 50 * (3 * 2 + 2 * 1));
  EXPECT_EQ(s.lost, 0);
  for (const auto& [to, player, sent, arrival] : h.got) {
    EXPECT_NE(h.robots[to].player, player);  // never our own packet back
    EXPECT_EQ(arrival, sent);                // delay 0: the same exchange
  }
  for (int t : h.teams_seen) EXPECT_EQ(t, 0);  // nobody heard the other team
}

// 30 % loss over 10 000+ (packet, teammate) pairs per seed, 5 seeds: each
// observed rate within 0.015 of 0.3 (binomial sigma 0.0045 at this count:
// > 3 sigma); delay 100 ms: every packet arrives 100 ms after it was sent
// (the exchange runs on 10 ms ticks and 100 ms is a whole number of them).
TEST(TeamNetwork, LossRateAndDelayAsConfigured) {
  TeamNetworkConfig c;
  c.loss = 0.3;
  c.delay_ms = 100;
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    Harness h(c, seed, kTwoTeams);
    h.run(130000, 20);  // 1300 s
    const TeamNetworkStats& s = h.net.stats();
    const double pairs = static_cast<double>(s.lost + s.delivered + h.net.inFlight());
    ASSERT_GT(pairs, 10000);
    const double rate = s.lost / pairs;
    std::printf("seed %llu: loss %.4f over %.0f (packet, teammate) pairs\n", static_cast<unsigned long long>(seed),
                rate, pairs);
    EXPECT_NEAR(rate, 0.3, 0.015) << "seed " << seed;
    for (const auto& [to, player, sent, arrival] : h.got) EXPECT_EQ(arrival - sent, 100000);
    EXPECT_EQ(static_cast<int64_t>(h.got.size()), s.delivered);
  }
}

// A delay that is not a whole number of ticks arrives at the next tick:
// within [delay, delay + 10 ms).
TEST(TeamNetwork, OffTickDelayRoundsUpToTheNextExchange) {
  TeamNetworkConfig c;
  c.delay_ms = 45;
  Harness h(c, 3, {{0, 1}, {0, 2}});
  h.run(500);
  ASSERT_FALSE(h.got.empty());
  for (const auto& [to, player, sent, arrival] : h.got) {
    EXPECT_GE(arrival - sent, 45000);
    EXPECT_LT(arrival - sent, 55000);
  }
}

TEST(TeamNetwork, BudgetPerTeamPerGameIsEnforced) {
  TeamNetworkConfig c;
  c.budget = 100;
  Harness h(c, 1, kTwoTeams);
  h.run(3000);  // 30 s: team 0 tries 450, team 1 tries 300
  const TeamNetworkStats& s = h.net.stats();
  EXPECT_EQ(s.team_sent[0], 100);
  EXPECT_EQ(s.team_sent[1], 100);
  EXPECT_EQ(s.over_budget, 450 + 300 - 200);
  EXPECT_EQ(h.net.teamBudgetLeft(0), 0);
  EXPECT_EQ(s.delivered, 100 * 2 + 100 * 1);
  TeamNetwork unlimited({}, 1);
  EXPECT_EQ(unlimited.teamBudgetLeft(0), -1);
}

TEST(TeamNetwork, SameSeedSameDeliveriesOtherSeedOthers) {
  TeamNetworkConfig c;
  c.loss = 0.5;
  c.delay_ms = 30;
  Harness a(c, 7, kTwoTeams), b(c, 7, kTwoTeams), d(c, 8, kTwoTeams);
  a.run(2000);
  b.run(2000);
  d.run(2000);
  EXPECT_EQ(a.got, b.got);
  EXPECT_NE(a.got, d.got);
}

TEST(TeamNetwork, FullInboxIsCountedNotFatal) {
  Harness h({}, 1, {{0, 1}, {0, 2}});
  h.run(2000, 20, /*read=*/false);  // nobody reads: 100 packets each way, 32 slots
  EXPECT_EQ(h.net.stats().inbox_overflow, 2 * (100 - static_cast<int64_t>(al::kInboxSlots)));
}

TEST(TeamNetwork, RejectsBadConfiguration) {
  TeamNetworkConfig c;
  c.loss = 1.5;
  EXPECT_THROW(TeamNetwork(c, 1), std::invalid_argument);
  c = {};
  c.delay_ms = -1;
  EXPECT_THROW(TeamNetwork(c, 1), std::invalid_argument);
}

// The outbox is shared memory the robot program writes: a head moved far
// past the tail (a hostile or broken program) is drained a ring's worth
// per exchange, not four billion packets (issue 45).
TEST(TeamNetwork, AnOutboxHeadFarPastItsTailDrainsOneRingPerExchange) {
  Harness h({}, 1, {{0, 1}, {0, 2}});
  h.links[0]->outbox.head.store(1u << 30);
  h.net.exchange(10000, h.ptrs);
  EXPECT_LE(h.net.stats().sent, static_cast<int64_t>(al::kOutboxSlots));
  EXPECT_EQ(h.links[0]->outbox.head.load() - h.links[0]->outbox.tail.load(), (1u << 30) - al::kOutboxSlots);
}

// The recording's deliveries (lastDelivered) are what a receiver took: a
// Lan packet its receiver's network refused (no network of its own, a
// unicast to another robot), or with no network at all, is not delivered.
TEST(TeamNetwork, ALanPacketIsDeliveredOnlyIfTheReceiversNetworkTookIt) {
  Harness h({}, 1, {{0, 1}, {0, 2}, {0, 3}});
  const uint8_t bytes[] = {1, 2, 3};
  h.net.send(0, bytes, sizeof bytes, 10000, Channel::Lan);
  h.net.exchange(10000, h.ptrs, [](const Delivery& d) { return d.to == 1; });  // robot 2 refuses
  ASSERT_EQ(h.net.lastDelivered().size(), 1u);
  EXPECT_EQ(h.net.lastDelivered()[0].to, 1);
  EXPECT_EQ(h.net.stats().lan_refused, 1);
  h.net.send(0, bytes, sizeof bytes, 20000, Channel::Lan);
  h.net.exchange(20000, h.ptrs);  // no robot has a network of its own
  EXPECT_TRUE(h.net.lastDelivered().empty());
  EXPECT_EQ(h.net.lastSent().size(), 1u);  // sent all the same
}
