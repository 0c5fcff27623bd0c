// Robot-code side of team communication: TeamSender's 5 Hz pacing,
// TeamReceiver's per-teammate state, the TeamLink rings, GameStateReader.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "agent/comms/GameStateReader.hpp"
#include "agent/comms/TeamReceiver.hpp"
#include "agent/comms/TeamSender.hpp"

using namespace agent::comms;
namespace al = common::libagent;

namespace {
SplMessage from(int team, int player, float x = 0) {
  SplMessage m;
  m.team = team;
  m.player = player;
  m.pose_x = x;
  return m;
}
}  // namespace

// Perception frames come at 30 Hz on 10 ms ticks (the runner's rule: frame k
// when t_us * 30 / 1e6 reaches k); over 60 s the sender sends 5 times a
// second with no gap under 200 ms.
TEST(TeamSender, SendsAtFiveHzFromThirtyHzFrames) {
  MemoryTransport t;
  TeamSender tx(0, 2);
  int64_t last_frame = -1, last_sent = -1, min_gap = 1 << 30, max_gap = 0;
  for (int64_t tick = 1; tick <= 6000; ++tick) {
    const int64_t t_us = tick * 10000;
    const int64_t frame = t_us * 30 / 1000000;
    if (frame <= last_frame) continue;
    last_frame = frame;
    if (tx.maybeSend(t, t_us, from(5, 5))) {
      if (last_sent >= 0) {
        min_gap = std::min(min_gap, t_us - last_sent);
        max_gap = std::max(max_gap, t_us - last_sent);
      }
      last_sent = t_us;
    }
  }
  // 60 s at one packet per 200-210 ms (frame times fall on 10 ms ticks).
  EXPECT_GE(tx.sent(), 285);
  EXPECT_LE(tx.sent(), 300);
  EXPECT_GE(min_gap, 200000);
  EXPECT_LE(max_gap, 240000);
  // The sender stamps our team and player, whatever the content said.
  const ParseResult r = parse(t.sent.front());
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.message.team, 0);
  EXPECT_EQ(r.message.player, 2);
}

TEST(TeamReceiver, KeepsTeammatesAndIgnoresOthers) {
  MemoryTransport t;
  TeamReceiver rx(0, 2);
  t.deliver(serialise(from(0, 3, 100.f)), 1000000);
  t.deliver(serialise(from(0, 4, 200.f)), 1100000);
  t.deliver(serialise(from(1, 3, 300.f)), 1100000);  // other team
  t.deliver(serialise(from(0, 2, 400.f)), 1100000);  // our own number
  t.deliver({'S', 'P', 'L'}, 1100000);                // truncated
  rx.update(t, 1200000);
  EXPECT_EQ(rx.stats().received, 5);
  EXPECT_EQ(rx.stats().accepted, 2);
  EXPECT_EQ(rx.stats().other_team, 1);
  EXPECT_EQ(rx.stats().own, 1);
  EXPECT_EQ(rx.stats().malformed, 1);
  EXPECT_EQ(rx.stats().last_error, ParseError::TooShort);
  ASSERT_TRUE(rx.teammate(3).heard);
  EXPECT_EQ(rx.teammate(3).last.pose_x, 100.f);
  EXPECT_FALSE(rx.teammate(5).heard);
  EXPECT_NEAR(rx.secondsSinceHeard(3, 1500000), 0.5, 1e-9);
  EXPECT_NEAR(rx.secondsSinceHeard(4, 1500000), 0.4, 1e-9);
  EXPECT_TRUE(std::isinf(rx.secondsSinceHeard(5, 1500000)));
  // A later packet replaces the state; an update with nothing keeps it.
  t.deliver(serialise(from(0, 3, 150.f)), 2000000);
  rx.update(t, 2000000);
  rx.update(t, 2500000);
  EXPECT_EQ(rx.teammate(3).last.pose_x, 150.f);
  EXPECT_EQ(rx.teammate(3).packets, 2);
  EXPECT_NEAR(rx.secondsSinceHeard(3, 2500000), 0.5, 1e-9);
}

TEST(TeamLink, RingsAreFifoAndCountOverflow) {
  auto link = std::make_unique<al::TeamLink>();
  TeamLinkTransport t(link.get());
  for (int i = 0; i < 6; ++i) t.send(serialise(from(0, 1, static_cast<float>(i))));
  EXPECT_EQ(link->outbox.size(), al::kOutboxSlots);
  EXPECT_EQ(link->outbox.overflows.load(), 6 - static_cast<int>(al::kOutboxSlots));
  al::TeamPacket p;
  for (uint32_t i = 0; i < al::kOutboxSlots; ++i) {
    ASSERT_TRUE(link->outbox.pop(p));
    EXPECT_EQ(parse(p.bytes, p.size).message.pose_x, static_cast<float>(i));
  }
  EXPECT_FALSE(link->outbox.pop(p));
  // Inbox: what the simulator pushed comes out of receive() in order.
  const auto b = serialise(from(0, 4));
  ASSERT_TRUE(link->inbox.push(b.data(), b.size(), 123, 4));
  ASSERT_TRUE(link->inbox.push(b.data(), b.size(), 456, 4));
  const auto got = t.receive();
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].time_us, 123);
  EXPECT_EQ(got[1].time_us, 456);
  EXPECT_EQ(got[0].bytes, b);
  EXPECT_TRUE(t.receive().empty());
  // Too large for a slot: refused and counted.
  std::vector<uint8_t> big(al::kMaxTeamPacketBytes + 1);
  EXPECT_FALSE(t.send(big));
}

TEST(GameStateReader, ReadsStatePenaltyAndTimers) {
  GameStateReader reader(5, 3);  // SPL team 5, player 3
  EXPECT_FALSE(reader.read(nullptr).valid);
  al::GameStateBlock b{};
  EXPECT_FALSE(reader.read(&b).valid);  // never written
  EXPECT_FALSE(reader.read(&b).mayMove());
  b.magic = al::kGameStateMagic;
  b.updates = 1;
  b.state = static_cast<uint8_t>(al::GameStateValue::Playing);
  b.teams[0].team_number = 19;  // the block names each side by its SPL number
  b.teams[1].team_number = 5;
  b.kickoff_team = 5;
  b.secs_remaining = 412;
  b.teams[1].players[2].penalty = static_cast<uint8_t>(al::Penalty::PlayerPushing);
  b.teams[1].players[2].secs_till_unpenalised = 27;
  GameState g = reader.read(&b);
  ASSERT_TRUE(g.valid);
  EXPECT_EQ(g.state, al::GameStateValue::Playing);
  EXPECT_TRUE(g.penalised);
  EXPECT_EQ(g.penalty, al::Penalty::PlayerPushing);
  EXPECT_EQ(g.secs_till_unpenalised, 27);
  EXPECT_EQ(g.secs_remaining, 412);
  EXPECT_TRUE(g.our_kickoff);
  EXPECT_EQ(g.kickoff_team, 5);
  EXPECT_FALSE(GameStateReader(7, 3).read(&b).valid);  // a team not in this game
  EXPECT_FALSE(g.mayMove());  // penalised
  // Another robot of the same team is not penalised.
  g = GameStateReader(5, 2).read(&b);
  EXPECT_FALSE(g.penalised);
  EXPECT_TRUE(g.mayMove());
  EXPECT_FALSE(GameStateReader(19, 2).read(&b).our_kickoff);
  b.state = static_cast<uint8_t>(al::GameStateValue::Set);
  EXPECT_FALSE(GameStateReader(5, 2).read(&b).mayMove());
  b.state = 77;  // garbage: treated as INITIAL (stand)
  EXPECT_EQ(GameStateReader(5, 2).read(&b).state, al::GameStateValue::Initial);
}
