// The GameController on the network, as an unchanged robot program hears
// it: with `game: {udp: on}` the runner hands this sender the game state
// once per tick (stage 11, teamAndGame) and it sends the SPL game-data
// packet of the scenario's version (2017's by default:
// sim/game/GameControlVersions.hpp) every 500 ms of simulated time,
// from t = 0, to a loopback address; it also reads, without blocking, the
// return packets ("RGrt") robots send to return_port and counts them per
// (team, player).
//
// Determinism: what is sent depends on the simulated state only, and what
// is received is counted, never acted on (a robot's manual penalise
// message does not penalise it here), so the simulation's own state does
// not depend on the network. A program that takes its game state from
// these packets reads them on its own thread, not in lock-step: see
// docs/game.md, "The GameController on UDP".
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/libagent/GameState.hpp"

namespace simswift::game {

namespace spl {
struct PacketVersion;
}

struct GameUdpConfig {
  bool on = false;
  // Where the packets go: an IPv4 address on the loopback network
  // (127.0.0.0/8) so a simulated game never reaches real robots;
  // 127.255.255.255 reaches every program bound to `port` with SO_REUSEADDR.
  std::string address = "127.0.0.1";
  int port = 3838;         // robots' game-data port (SPL: 3838)
  int return_port = 3939;  // where return packets are read (SPL: 3939); 0 = any free port
  // The packets' version: the season the robot programs were written for
  // (sim/game/GameControlVersions.hpp: 10 for 2017, 12-18 for 2019-2025).
  int version = 10;
  // What each team may still send, in the packets of 2022 on (their
  // messageBudget; the GameController's rule for a game): an assumption,
  // the SPL's 1200 per game of those years, not counted down.
  int message_budget = 1200;
};

// True if `s` is a dotted IPv4 address in 127.0.0.0/8.
bool isLoopbackAddress(const std::string& s);

class GameControllerUdp {
 public:
  // Opens the sockets; throws std::runtime_error naming the address and
  // port if it cannot (e.g. return_port taken by another run).
  explicit GameControllerUdp(const GameUdpConfig& config);
  ~GameControllerUdp();
  GameControllerUdp(const GameControllerUdp&) = delete;
  GameControllerUdp& operator=(const GameControllerUdp&) = delete;

  // Stage 11: sends `b` (GameController::fill's block) if a packet is due
  // at simulated time t_us, then counts the return packets waiting.
  void update(int64_t t_us, const common::libagent::GameStateBlock& b);

  // Robots with a network of their own (sim/network/RobotLan.hpp): every
  // packet sent is also handed here, and their return packets, read from
  // their networks, are counted through countReturn as those on return_port.
  void alsoSendTo(std::function<void(const std::vector<uint8_t>&)> sink) { also_ = std::move(sink); }
  void countReturn(const uint8_t* bytes, size_t size);

  // Return packets from one robot (team: SPL team number in the packet).
  struct Returns {
    int team = 0, player = 0;
    int64_t packets = 0;
    int64_t alive = 0, penalise = 0, unpenalise = 0;  // by message
  };
  std::vector<Returns> returns() const;  // by (team, player)
  int64_t sent() const { return sent_; }
  int64_t sendErrors() const { return send_errors_; }
  int64_t badReturns() const { return bad_returns_; }  // wrong size, header or version
  int returnPort() const { return return_port_; }      // the port bound (return_port 0: the one picked)
  const GameUdpConfig& config() const { return config_; }

 private:
  void drainReturns();

  GameUdpConfig config_;
  const spl::PacketVersion* version_;  // config_.version's layout
  int send_fd_ = -1, recv_fd_ = -1;
  uint32_t dest_addr_ = 0;  // network byte order
  int return_port_ = 0;
  int64_t next_send_us_ = 0;
  uint8_t packet_number_ = 0;
  int64_t sent_ = 0, send_errors_ = 0, bad_returns_ = 0;
  std::map<std::pair<int, int>, Returns> returns_;
  std::function<void(const std::vector<uint8_t>&)> also_;
};

}  // namespace simswift::game
