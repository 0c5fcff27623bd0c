// The UDP GameController (game: {udp: on}): the 2017 packet's bytes where
// the SPL GameController puts them, a plain UDP listener that decodes the
// packets of a run and sees the timeline's states and a penalty at 2 Hz of
// simulated time, return packets counted, the state hash untouched, and bad
// configuration refused with file, line and field.
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "sim/game/GameControlPacket.hpp"
#include "sim/game/GameControllerUdp.hpp"
#include "sim/runner/Runner.hpp"
#include "tests/support/ConfigErrors.hpp"
#include "tests/support/Sockets.hpp"

using simswift::ConfigError;
using simswift::runner::Runner;
using simswift::runner::RunnerError;
using simswift::runner::Scenario;
namespace al = common::libagent;
namespace spl = simswift::game::spl;

namespace {
using Listener = simswift::testing::UdpListener;
using simswift::testing::sendUdp;

std::string errorOf(const std::string& yaml) {
  return simswift::testing::configError([&] { Scenario::parse(yaml, "s.yaml"); });
}

uint16_t le16(const unsigned char* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }
}  // namespace

// Offsets from the 2017 GameController's packing order (GameControlData.java,
// TeamInfo.java): 20 bytes of game fields, then two 284-byte teams whose
// players start at byte 262 (after the 253-byte coach message and the coach).
TEST(GameControllerUdp, PacketBytesAsTheGameControllerPacksThem) {
  al::GameStateBlock b{};
  b.state = static_cast<uint8_t>(al::GameStateValue::Ready);
  b.secondary_state = 0;
  b.first_half = 1;
  b.kickoff_team = 19;
  b.secs_remaining = 0x0259;  // 601
  b.secondary_time = 45;
  b.teams[0].team_number = 19;
  b.teams[1].team_number = 5;
  b.teams[1].team_colour = 1;
  b.teams[1].players[2] = {static_cast<uint8_t>(al::Penalty::PlayerPushing), 30};
  const spl::GameControlData d = spl::encode(b, 7);
  unsigned char w[sizeof d];
  std::memcpy(w, &d, sizeof d);
  ASSERT_EQ(sizeof w, 588u);
  EXPECT_EQ(std::string(reinterpret_cast<char*>(w), 4), "RGme");
  EXPECT_EQ(le16(w + 4), 10);  // version
  EXPECT_EQ(w[6], 7);          // packet number
  EXPECT_EQ(w[7], 6);          // players per team (SPL 2017)
  EXPECT_EQ(w[9], 1);          // READY
  EXPECT_EQ(w[10], 1);         // first half
  EXPECT_EQ(w[11], 19);        // kick-off team
  EXPECT_EQ(le16(w + 14), 0xFFFF);  // no drop-in yet
  EXPECT_EQ(le16(w + 16), 601);
  EXPECT_EQ(le16(w + 18), 45);
  EXPECT_EQ(w[20], 19);            // teams[0].teamNumber
  EXPECT_EQ(w[20 + 284], 5);       // teams[1].teamNumber
  EXPECT_EQ(w[20 + 284 + 1], 1);   // teams[1].teamColour
  const unsigned char* p3 = w + 20 + 284 + 262 + 2 * 2;  // teams[1], player 3
  EXPECT_EQ(p3[0], 2);   // PENALTY_SPL_PLAYER_PUSHING
  EXPECT_EQ(p3[1], 30);  // s till unpenalised
  spl::GameControlData back;
  EXPECT_TRUE(spl::decode(w, sizeof w, &back));
  EXPECT_EQ(back.teams[1].players[2].secs_till_unpenalised, 30);

  const spl::ReturnData r = spl::makeReturn(19, 3, spl::ReturnMessage::Alive);
  unsigned char rw[sizeof r];
  std::memcpy(rw, &r, sizeof r);
  const unsigned char expect[8] = {'R', 'G', 'r', 't', 2, 19, 3, 2};
  EXPECT_EQ(std::memcmp(rw, expect, 8), 0);
}

TEST(GameControllerUdp, DecodersRefuseOtherPackets) {
  al::GameStateBlock b{};
  spl::GameControlData d = spl::encode(b, 0);
  spl::GameControlData out;
  std::string why;
  EXPECT_FALSE(spl::decode(&d, sizeof d - 1, &out, &why));
  EXPECT_EQ(why, "587 bytes (expected 588)");
  d.version = 11;
  EXPECT_FALSE(spl::decode(&d, sizeof d, &out, &why));
  EXPECT_EQ(why, "version 11 (expected 10)");
  spl::ReturnData r = spl::makeReturn(1, 1, spl::ReturnMessage::Alive);
  r.header[3] = 'x';
  spl::ReturnData rout;
  EXPECT_FALSE(spl::decodeReturn(&r, sizeof r, &rout, &why));
  EXPECT_EQ(why, "header is not RGrt");
}

namespace {
// Team 19 players 1 and 2 against team 5 player 1; INITIAL, then READY at
// 0.5 s, SET at 1 s, PLAYING at 1.5 s; robot 1 (t19p2) penalised at 1.6 s
// for 0.6 s. 2.5 s of simulated time.
std::string scenario(const std::string& udp) {
  return "duration: 2.5\nseed: 5\nnoise: off\n"
         "robots:\n"
         "  - {team: 19, player: 1, x: -1.0, y: 0.5}\n"
         "  - {team: 19, player: 2, x: -1.0, y: -1.0}\n"
         "  - {team: 5, player: 1, x: 1.0, y: 0.0, theta: 3.14159}\n"
         "game:\n"
         "  state: initial\n"
         "  timeline: [{t: 0.5, state: ready}, {t: 1.0, state: set}, {t: 1.5, state: playing}]\n"
         "  penalties: [{t: 1.6, robot: 1, penalty: request_for_pickup, duration: 0.6}]\n" +
         udp;
}
}  // namespace

TEST(GameControllerUdp, ListenerSeesTheTimelineAndThePenalty) {
  Listener gc;
  Runner r(Scenario::parse(scenario("  udp: on\n  port: " + std::to_string(gc.port) + "\n  return_port: 0\n"),
                           "udp.yaml"));
  r.start();
  std::vector<spl::GameControlData> got;
  std::vector<int64_t> at_tick;
  auto collect = [&] {
    for (const auto& bytes : gc.drain()) {
      spl::GameControlData d;
      std::string why;
      ASSERT_TRUE(spl::decode(bytes.data(), bytes.size(), &d, &why)) << why;
      got.push_back(d);
      at_tick.push_back(r.ticks());
    }
  };
  collect();
  while (r.ticks() < 250) {
    r.tick();
    collect();
  }
  // 2 Hz of simulated time from t = 0: t = 0, 0.5, ..., 2.5 s, each
  // heard in the tick that sent it.
  ASSERT_EQ(got.size(), 6u);
  for (size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(at_tick[i], static_cast<int64_t>(50 * i));
    EXPECT_EQ(got[i].packet_number, i);
    EXPECT_EQ(got[i].teams[0].team_number, 19);
    EXPECT_EQ(got[i].teams[1].team_number, 5);
  }
  using S = al::GameStateValue;
  const S states[6] = {S::Initial, S::Ready, S::Set, S::Playing, S::Playing, S::Playing};
  for (size_t i = 0; i < 6; ++i) EXPECT_EQ(got[i].state, static_cast<uint8_t>(states[i])) << "packet " << i;
  EXPECT_EQ(got[1].secondary_time, 45);       // READY's countdown, just begun
  EXPECT_EQ(got[5].secs_remaining, 600 - 1);  // PLAYING for 1 s of the 600 s half
  // Robot 1 (t19p2) penalised from 1.6 s to 2.2 s: the 2.0 s packet says so.
  const auto& p2 = [&](int i) { return got[i].teams[0].players[1]; };
  EXPECT_EQ(p2(3).penalty, 0);
  EXPECT_EQ(p2(4).penalty, static_cast<uint8_t>(al::Penalty::RequestForPickup));
  EXPECT_EQ(p2(4).secs_till_unpenalised, 1);  // 0.2 s left, rounded up
  EXPECT_EQ(p2(5).penalty, 0);
  EXPECT_EQ(got[4].teams[0].players[0].penalty, 0);
  EXPECT_EQ(r.gameControllerUdp()->sent(), 6);
  r.shutdown();
}

TEST(GameControllerUdp, ReturnPacketsCountedPerRobot) {
  Listener gc;
  Runner r(Scenario::parse(scenario("  udp: on\n  port: " + std::to_string(gc.port) + "\n  return_port: 0\n"),
                           "udp.yaml"));
  r.start();
  const int port = r.gameControllerUdp()->returnPort();
  ASSERT_GT(port, 0);
  const spl::ReturnData alive = spl::makeReturn(19, 2, spl::ReturnMessage::Alive);
  const spl::ReturnData pen = spl::makeReturn(5, 1, spl::ReturnMessage::ManualPenalise);
  for (int i = 0; i < 3; ++i) sendUdp(port, &alive, sizeof alive);
  sendUdp(port, &pen, sizeof pen);
  sendUdp(port, "RGrt", 4);  // too short
  r.tick();
  const auto c = r.gameControllerUdp()->returns();
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].team, 5);
  EXPECT_EQ(c[0].penalise, 1);
  EXPECT_EQ(c[1].team, 19);
  EXPECT_EQ(c[1].player, 2);
  EXPECT_EQ(c[1].packets, 3);
  EXPECT_EQ(c[1].alive, 3);
  EXPECT_EQ(r.gameControllerUdp()->badReturns(), 1);
  // Counted, never acted on: the manual penalise message penalised nobody.
  EXPECT_FALSE(r.gameController().penalised(2));
  EXPECT_NE(r.stats().summary().find("gc udp 1 sent, returns t5p1 1 t19p2 3"), std::string::npos)
      << r.stats().summary();
  r.shutdown();
}

// The simulation never reads the network: the same state hash with the
// packets on or off (the robots here read the extension block).
TEST(GameControllerUdp, StateHashUntouched) {
  Listener gc;
  auto hash = [&](const std::string& udp) {
    Runner r(Scenario::parse(scenario(udp), "h.yaml"));
    r.start();
    while (r.ticks() < 200) r.tick();
    const uint64_t h = r.stats().hash;
    r.shutdown();
    return h;
  };
  EXPECT_EQ(hash("  udp: on\n  port: " + std::to_string(gc.port) + "\n  return_port: 0\n"), hash(""));
}

TEST(GameControllerUdp, ReturnPortTakenIsARunnerError) {
  Listener taken;
  Runner r(Scenario::parse(scenario("  udp: on\n  port: 9\n  return_port: " + std::to_string(taken.port) + "\n"),
                           "busy.yaml"));
  try {
    r.start();
    FAIL() << "expected a RunnerError";
  } catch (const RunnerError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("127.0.0.1:" + std::to_string(taken.port)), std::string::npos) << m;
    EXPECT_NE(m.find("busy.yaml"), std::string::npos) << m;
  }
}

TEST(GameControllerUdp, ConfigParsesAndBadValuesNameFileLineAndField) {
  const std::string robots = "robots:\n  - {team: 0, player: 2}\n";
  const Scenario s = Scenario::parse(robots + "game: {udp: on, port: 4000, return_port: 0, address: 127.0.0.2}\n",
                                     "s.yaml");
  EXPECT_TRUE(s.game.udp.on);
  EXPECT_EQ(s.game.udp.port, 4000);
  EXPECT_EQ(s.game.udp.return_port, 0);
  EXPECT_EQ(s.game.udp.address, "127.0.0.2");
  const Scenario d = Scenario::parse(robots + "game: {udp: on}\n", "s.yaml");
  EXPECT_EQ(d.game.udp.port, spl::kDataPort);
  EXPECT_EQ(d.game.udp.return_port, spl::kReturnPort);
  EXPECT_FALSE(Scenario::parse(robots, "s.yaml").game.udp.on);

  struct Case { std::string yaml, message; };
  const Case cases[] = {
      {"game: {udp: on, port: 70000}\n", "s.yaml:3: game.port: must be in [1, 65535] (got 70000)"},
      {"game: {udp: on, return_port: -1}\n", "s.yaml:3: game.return_port: must be in [0, 65535]"},
      {"game: {udp: on, port: 3838, return_port: 3838}\n", "s.yaml:3: game.return_port: must differ from port"},
      {"game: {port: 4000}\n", "s.yaml:3: game.port: needs udp: on"},
      {"game: {udp: maybe}\n", "s.yaml:3: game.udp: expected true or false"},
      {"game: {udp: on, address: 192.168.1.5}\n", "s.yaml:3: game.address: must be an IPv4 address in 127.0.0.0/8"},
      {"game: {udp: on, address: localhost}\n", "s.yaml:3: game.address: must be an IPv4 address in 127.0.0.0/8"},
      {"game: {udp: on, prot: 4000}\n", "s.yaml:3: unknown key 'prot' in game"},
  };
  for (const Case& c : cases) {
    const std::string e = errorOf(robots + c.yaml);
    EXPECT_NE(e.find(c.message), std::string::npos) << c.yaml << " gave: " << e;
  }
}
