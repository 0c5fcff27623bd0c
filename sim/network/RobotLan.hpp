// Everything that crosses the robots' own networks (docs/porting.md,
// "Network"): each robot with a network of its own has a wlan0 whose other
// end (a TAP descriptor) simswift holds. Once per tick, in stage 11
// (teamAndGame, sim/runner/Runner.hpp), before the team network's exchange:
//   - every robot's wlan0 is read, non-blocking, robot by robot in scenario
//     order, frames in the order the robot wrote them (at most
//     kMaxFramesPerTick: a flood cannot stall the run); each frame is parsed
//     and checked (sim/network/UdpFrame.hpp: it is another process's bytes);
//   - a team message (UDP to 10000 + its team's number, to 10.0.255.255,
//     255.255.255.255 or a 10.0.x.y address) goes into the team network
//     (TeamNetwork: loss, delay, budget, in simulated time, seeded), to its
//     teammates only; delivered, it is written into each receiving
//     teammate's wlan0 from the sender's address and port, to the address
//     it was sent to (a unicast reaches only the robot with that address);
//   - a return packet (UDP to 3939 of the GameController's address) is
//     counted as those the GameController reads on the machine
//     (GameControllerUdp::countReturn);
//   - every other frame is dropped (counted: IPv6 and the like, other ports).
// The GameController's packets are written into every robot's wlan0 when
// they are sent (every 500 ms of simulated time), from
// kGameControllerAddress:3838 to 10.0.255.255:3838. The packet of t = 0,
// sent when the run starts, before the programs have attached (and bound
// their sockets), is held and written at the first tick's stage 11, so every
// robot gets it, in every run alike: the lan goes live at its first
// readFrames, which the Runner makes from the first tick on, never at start
// (Runner::teamAndGame).
//
// Determinism: what a program sends is read at one stage of the tick, so a
// program that sends from its lock-step cycle (before answering LoLA or
// libagent) has its packets read at the same tick every run.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sim/network/TeamNetwork.hpp"
#include "sim/network/UdpFrame.hpp"

namespace simswift::network {

// simswift's GameController's address on the robots' network: no robot has
// it (team 255 would be the broadcast network's last number).
constexpr uint32_t kGameControllerAddress = (10u << 24) | (255u << 8) | 254u;  // 10.0.255.254
constexpr uint16_t kGameDataPort = 3838;    // SPL: robots read the GameController here
constexpr uint16_t kGameReturnPort = 3939;  // SPL: robots answer here
constexpr uint16_t kTeamPortBase = 10000;   // SPL: team messages on 10000 + team number
constexpr int kMaxFramesPerTick = 256;      // per robot

struct RobotLanStats {
  int64_t frames_read = 0;
  int64_t team_sent = 0;        // team messages handed to the team network
  int64_t team_written = 0;     // team messages written into a teammate's wlan0
  int64_t game_written = 0;     // GameController packets written (one per robot)
  int64_t returns = 0;          // return packets handed to the GameController
  int64_t dropped = 0;          // frames neither (another port, IPv6, ARP...)
  int64_t refused = 0;          // frames that failed the checks (UdpFrame.hpp)
  int64_t write_errors = 0;     // writes into a wlan0 that failed (its program gone)
  std::string last_refusal;     // why, for the last one refused
};

class RobotLan {
 public:
  RobotLan() = default;
  ~RobotLan();
  RobotLan(const RobotLan&) = delete;
  RobotLan& operator=(const RobotLan&) = delete;

  // Robot `endpoint` (its team network endpoint: robot index) has a wlan0
  // whose TAP descriptor is `fd` (taken over: closed here).
  void add(int endpoint, int team_number, int player, int fd);
  bool empty() const { return robots_.empty(); }

  // Stage 11 (above): reads every wlan0 into `net` and `game_return`.
  void readFrames(int64_t t_us, TeamNetwork& net, const std::function<void(const uint8_t*, size_t)>& game_return);
  // A team message the network delivers (Channel::Lan), into its receiver's
  // wlan0; false if not written (no network of its own, a unicast to
  // another robot, the write failed).
  bool deliver(const Delivery& d);
  // The GameController's packet, into every wlan0.
  void sendGameData(const std::vector<uint8_t>& payload);

  const RobotLanStats& stats() const { return stats_; }

 private:
  struct Robot {
    int endpoint, team_number, player, fd;
    uint32_t address;
  };
  const Robot* byEndpoint(int endpoint) const;
  bool write(const Robot& r, const UdpDatagram& d);

  std::vector<Robot> robots_;
  bool live_ = false;                          // readFrames has run once: the programs are attached
  std::vector<std::vector<uint8_t>> pending_;  // GameController packets from before that
  RobotLanStats stats_;
  uint16_t ip_id_ = 0;
};

}  // namespace simswift::network
