// The GameController packets of the NAO V6 seasons (game: {udp: on,
// version: N}): each version's bytes where the public GameController's C
// header of that season puts them (sim/game/GameControlVersions.hpp cites
// the commits), a run's packets at the chosen version, the era's return
// packets counted, and an unknown version refused with file, line and field.
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "sim/game/GameControlVersions.hpp"
#include "sim/runner/Runner.hpp"
#include "tests/support/ConfigErrors.hpp"
#include "tests/support/Sockets.hpp"

using simswift::runner::Runner;
using simswift::runner::Scenario;
namespace al = common::libagent;
namespace spl = simswift::game::spl;

namespace {

uint16_t le16(const std::vector<uint8_t>& p, size_t at) { return static_cast<uint16_t>(p[at] | (p[at + 1] << 8)); }

al::GameStateBlock sampleState() {
  al::GameStateBlock b{};
  b.state = static_cast<uint8_t>(al::GameStateValue::Playing);
  b.secondary_state = 1;  // penalty shoot-out: the game phase's number too
  b.first_half = 1;
  b.kickoff_team = 19;
  b.secs_remaining = 543;
  b.secondary_time = 7;
  b.teams[0].team_number = 19;
  b.teams[0].team_colour = 0;
  b.teams[0].score = 2;
  b.teams[1].team_number = 5;
  b.teams[1].team_colour = 1;
  b.teams[1].score = 1;
  b.teams[1].players[2].penalty = 8;  // player 3: request for pickup
  b.teams[1].players[2].secs_till_unpenalised = 25;
  return b;
}

}  // namespace

// Sizes from the C structs (no padding: every uint16 falls on an even byte):
// 18 bytes of game fields, then two teams of 6 + 2 x 6 (2019-2021),
// 8 + 2 x 7 (2022) or 10 + 2 x 20 (2023-2025) bytes.
TEST(GameControlVersions, EachSeasonsBytesWhereItsHeaderPutsThem) {
  struct Expect {
    int version;
    size_t bytes, team_bytes;
    int players_per_team;
  };
  for (const Expect& e : {Expect{12, 54, 18, 5}, Expect{13, 54, 18, 5}, Expect{14, 62, 22, 5},
                          Expect{15, 118, 50, 7}, Expect{17, 118, 50, 7}, Expect{18, 118, 50, 7}}) {
    SCOPED_TRACE(e.version);
    const spl::PacketVersion* v = spl::findPacketVersion(e.version);
    ASSERT_NE(v, nullptr);
    const std::vector<uint8_t> p = spl::encodeGameData(*v, sampleState(), 42, 1100);
    ASSERT_EQ(p.size(), e.bytes);
    EXPECT_EQ(v->data_bytes, e.bytes);
    EXPECT_EQ(std::string(p.begin(), p.begin() + 4), "RGme");
    EXPECT_EQ(p[4], e.version);
    EXPECT_EQ(p[5], 42);  // packet number
    EXPECT_EQ(p[6], e.players_per_team);
    EXPECT_EQ(p[9], 1);   // game phase: penalty shoot-out
    EXPECT_EQ(p[10], 3);  // state: playing
    EXPECT_EQ(p[12], 1);  // first half
    EXPECT_EQ(p[13], 19);  // kicking team
    EXPECT_EQ(le16(p, 14), 543);
    EXPECT_EQ(le16(p, 16), 7);
    const size_t t1 = 18 + e.team_bytes;  // teams[1]
    EXPECT_EQ(p[18], 19);
    EXPECT_EQ(p[t1], 5);
    EXPECT_EQ(p[t1 + 1], 1);  // colour (2023 on: the field players')
    const bool gk = e.version >= 15, budget = e.version >= 14;
    EXPECT_EQ(p[t1 + (gk ? 4 : 2)], 1);  // score
    if (gk) {
      EXPECT_EQ(p[t1 + 2], 1);  // goalkeeper colour
      EXPECT_EQ(p[t1 + 3], 1);  // goalkeeper: player 1
    }
    if (budget) {
      EXPECT_EQ(le16(p, t1 + (gk ? 8 : 6)), 1100);
    }
    const size_t players = t1 + (gk ? 10 : budget ? 8 : 6);
    // Player 3's penalty, request for pickup: 8 in 2019, 7 from 2020.
    EXPECT_EQ(p[players + 2 * 2], e.version == 12 ? 8 : 7);
    EXPECT_EQ(p[players + 2 * 2 + 1], 25);
    EXPECT_EQ(players + 2 * static_cast<size_t>(v->max_players), e.bytes);  // the players end the packet
  }
  EXPECT_EQ(spl::findPacketVersion(11), nullptr);
  EXPECT_EQ(spl::findPacketVersion(10)->data_bytes, 588u);  // 2017's, unchanged
}

// Each season's penalty numbers (the public headers' PENALTY_SPL_* at the
// commits GameControlVersions.hpp names): 2017 and 2019 alike for 1-8;
// from 2020 illegal position is 5, request for pickup 7, no kick-off goal.
TEST(GameControlVersions, PenaltiesByEachSeasonsNumbers) {
  using P = common::libagent::Penalty;
  for (int version : {10, 12}) {
    const spl::PacketVersion& v = *spl::findPacketVersion(version);
    EXPECT_EQ(spl::penaltyCode(v, P::IllegalDefender), 5);
    EXPECT_EQ(spl::penaltyCode(v, P::KickOffGoal), 7);
    EXPECT_EQ(spl::penaltyCode(v, P::RequestForPickup), 8);
  }
  for (int version : {13, 14, 15, 17, 18}) {
    SCOPED_TRACE(version);
    const spl::PacketVersion& v = *spl::findPacketVersion(version);
    EXPECT_EQ(spl::penaltyCode(v, P::None), 0);
    EXPECT_EQ(spl::penaltyCode(v, P::IllegalBallContact), 1);
    EXPECT_EQ(spl::penaltyCode(v, P::PlayerPushing), 2);
    EXPECT_EQ(spl::penaltyCode(v, P::IllegalMotionInSet), 3);
    EXPECT_EQ(spl::penaltyCode(v, P::InactivePlayer), 4);
    EXPECT_EQ(spl::penaltyCode(v, P::IllegalDefender), 5);  // illegal position
    EXPECT_EQ(spl::penaltyCode(v, P::LeavingTheField), 6);
    EXPECT_EQ(spl::penaltyCode(v, P::KickOffGoal), -1);
    EXPECT_EQ(spl::penaltyCode(v, P::RequestForPickup), 7);
    EXPECT_EQ(spl::penaltyCode(v, P::Substitute), 14);
    EXPECT_EQ(spl::penaltyCode(v, P::Manual), 15);
  }
}

// A scenario penalty its season's packets cannot carry is refused with
// file:line:key; the same with the 2019 packets is accepted.
TEST(GameControlVersions, APenaltyTheSeasonLacksIsRefused) {
  auto yaml = [](int version) {
    return "robots:\n  - {team: 19, player: 1}\ngame:\n  udp: on\n  version: " + std::to_string(version) +
           "\n  penalties:\n    - {t: 1, robot: 0, penalty: kick_off_goal}\n";
  };
  const std::string e = simswift::testing::configError([&] { Scenario::parse(yaml(13), "gc13.yaml"); });
  EXPECT_NE(e.find("gc13.yaml:7"), std::string::npos) << e;
  EXPECT_NE(e.find("penalty"), std::string::npos) << e;
  EXPECT_NE(e.find("version 13 (2020-2021) has no such penalty"), std::string::npos) << e;
  EXPECT_EQ(simswift::testing::configError([&] { Scenario::parse(yaml(12), "gc12.yaml"); }), "");
}

// Return packets: 8 bytes until 2021 (team, player, message: 0 alive),
// 32 from 2022 (player before team, then fallen, pose, ball age, ball).
TEST(GameControlVersions, ReturnPacketsOfEachEra) {
  spl::Return r;
  std::string why;
  const uint8_t v3[8] = {'R', 'G', 'r', 't', 3, 19, 2, 0};
  ASSERT_TRUE(spl::decodeReturnData(*spl::findPacketVersion(12), v3, sizeof v3, &r, &why)) << why;
  EXPECT_EQ(r.team, 19);
  EXPECT_EQ(r.player, 2);
  EXPECT_TRUE(r.alive);
  uint8_t v4[32] = {'R', 'G', 'r', 't', 4, 3, 19, 0};
  ASSERT_TRUE(spl::decodeReturnData(*spl::findPacketVersion(18), v4, sizeof v4, &r, &why)) << why;
  EXPECT_EQ(r.team, 19);
  EXPECT_EQ(r.player, 3);
  EXPECT_TRUE(r.alive);
  EXPECT_FALSE(spl::decodeReturnData(*spl::findPacketVersion(18), v3, sizeof v3, &r, &why));
  EXPECT_NE(why.find("8 bytes (expected 32)"), std::string::npos) << why;
  v4[4] = 3;
  EXPECT_FALSE(spl::decodeReturnData(*spl::findPacketVersion(14), v4, sizeof v4, &r, &why));
  EXPECT_NE(why.find("version 3 (expected 4)"), std::string::npos) << why;
}

// A run with version 14: a listener gets 62-byte packets every 500 ms of
// simulated time; a 2022 robot's return packets are counted.
TEST(GameControlVersions, ARunSendsTheScenariosVersion) {
  const simswift::testing::UdpListener listener;
  ASSERT_GT(listener.port, 0);
  const std::string yaml = "duration: 1.2\nrobots:\n  - {team: 19, player: 1}\ngame:\n  udp: on\n  version: 14\n  port: " +
                           std::to_string(listener.port) + "\n  return_port: 0\n  message_budget: 900\n";
  Runner r(Scenario::parse(yaml, "v14.yaml"));
  r.start();
  uint8_t ret[32] = {'R', 'G', 'r', 't', 4, 1, 19, 0};
  const int return_port = r.gameControllerUdp()->returnPort();
  for (int i = 0; i < 2; ++i) simswift::testing::sendUdp(return_port, ret, sizeof ret, listener.fd);
  simswift::runner::RunOptions o;
  o.progress = false;
  r.run(o);
  const std::vector<std::vector<unsigned char>> got = listener.drain();
  ASSERT_EQ(got.size(), 3u);  // t = 0, 0.5, 1.0 s
  for (const auto& p : got) {
    ASSERT_EQ(p.size(), 62u);
    EXPECT_EQ(p[4], 14);
    EXPECT_EQ(le16(p, 18 + 6), 900);  // message budget
  }
  const auto c = r.gameControllerUdp()->returns();
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].team, 19);
  EXPECT_EQ(c[0].alive, 2);
}

TEST(GameControlVersions, UnknownVersionRefusedWithFileLineAndField) {
  const std::string e = simswift::testing::configError([] {
    Scenario::parse("robots:\n  - {team: 19, player: 1}\ngame:\n  udp: on\n  version: 16\n", "g.yaml");
  });
  EXPECT_NE(e.find("g.yaml:5: game.version: simswift sends GameController packet versions 10 (2017-2018), 12 (2019)"),
            std::string::npos)
      << e;
  const std::string alone = simswift::testing::configError([] {
    Scenario::parse("robots:\n  - {team: 19, player: 1}\ngame:\n  version: 14\n", "g.yaml");
  });
  EXPECT_NE(alone.find("g.yaml:4: game.version: needs udp: on"), std::string::npos) << alone;
}
