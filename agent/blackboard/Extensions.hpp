// What the robot program's extension devices hold, as Blackboard sections:
// the game state the GameController (here the simulator) last wrote, the
// team packets that arrived, and the packets to send. The robot program
// copies the devices in before the Perception modules run (as it copies the
// camera frame) and puts the outbox on the team transport after them, so the
// game state and team modules read and write sections only, never a device
// (common/libagent/SimExtension.hpp has the devices; on a NAO they are the
// GameController's UDP packets and the team's broadcast socket).
#pragma once

#include <cstdint>
#include <vector>

#include "common/libagent/GameState.hpp"

namespace agent::blackboard {

// The game-state block at the start of this camera frame. present: the
// program has one (without it the game is unknown: a test field, PLAYING).
struct GameControllerData {
  bool present = false;
  common::libagent::GameStateBlock block{};
};

// One team packet: opaque bytes (agent/comms/SplMessage parses them).
struct ReceivedTeamPacket {
  std::vector<uint8_t> bytes;
  int64_t time_us = 0;  // arrival time (simulated); 0 if the transport does not know
};

// The packets that arrived since the previous camera frame, in arrival
// order. connected: the program has a team transport (none: no teammates).
struct TeamInbox {
  bool connected = false;
  std::vector<ReceivedTeamPacket> packets;
};

// The packets the team send module wants on the transport this frame.
struct TeamOutbox {
  std::vector<std::vector<uint8_t>> packets;
};

}  // namespace agent::blackboard
