// What simswift adds beside the libagent block, in an object of its own
// (/libagent-simswift<N>, SharedNames.hpp) so that AgentData stays exactly
// rUNSWift's and an unchanged libagent program, which never opens this
// object, runs as on the robot.
//
// Lock-step needs nothing from the program beyond libagent's own protocol:
// the simulator parks actuators_latest on kActuatorsParked after it consumes
// a command and counts the tick answered once a valid index reappears (the
// program's Effector wrote a slot, then set actuators_latest). A program
// that knows simswift (agent/'s AgentConnection) also posts `answered` after
// publishing, only to wake the simulator sooner; it reads the simulated time
// of its sensor slot here, announces itself (client_pid, camera consumer),
// takes camera frames, reads the game state, exchanges team packets and sees
// `shutdown`. It watches `simulator_pid` to notice a simulator that died
// without saying so.
#pragma once

#include <semaphore.h>

#include <atomic>
#include <cstdint>

#include "common/libagent/AgentShared.hpp"
#include "common/libagent/CameraShared.hpp"
#include "common/libagent/GameState.hpp"
#include "common/libagent/TeamLink.hpp"

namespace common::libagent {

constexpr uint32_t kExtensionMagic = 0x53575845;  // "SWXE"
// 4: camera hand-over sequence numbers; 5: CameraImages has a size per camera.
constexpr uint32_t kExtensionVersion = 5;

// Out-of-range actuators_latest: "no command since the last one consumed".
// A libagent Effector then picks actuators_read's slot (its slot loop stops
// on the read index), which the simulator is not reading in lock-step.
constexpr uint8_t kActuatorsParked = 0xFF;

enum class SyncMode : int32_t {
  LockStep = 0,     // the simulator waits for every tick's answer (default)
  FreeRunning = 1,  // --realtime: sends the latest command, counts skipped cycles
};

struct SimExtension {
  uint32_t magic;    // written last by the simulator (kExtensionMagic)
  uint32_t version;  // kExtensionVersion
  // The simulator owning this robot: pid and start time (clock ticks since
  // boot, /proc/<pid>/stat field 22) so a recycled pid is not taken for it.
  std::atomic<int32_t> simulator_pid;
  std::atomic<uint64_t> simulator_start;
  std::atomic<int32_t> sync_mode;  // SyncMode
  // Simulated time and tick of the sensors in each slot of AgentData::sensors.
  int64_t slot_time_us[kSlots];
  int64_t slot_tick[kSlots];
  std::atomic<int64_t> skipped;    // cycles whose post was skipped (semaphore > 0)
  std::atomic<int32_t> shutdown;   // the run is over: robot threads end
  // A simswift-aware program announces itself (its pid; 1 in-process) before
  // its threads answer the first tick.
  std::atomic<int32_t> client_pid;
  sem_t answered;     // wake-up hint, posted after actuators_latest is set
  CameraBlock camera; // 30 Hz frame handshake (CameraShared.hpp)
  // Written by the simulator only between ticks, while no robot thread runs
  // (Runner::tick() step 7).
  GameStateBlock game;  // the GameController's state as this robot sees it
  TeamLink team;        // team packets: outbox (robot code) and inbox (network)
};

// True if process `pid` runs and (when `start` != 0) started at `start`.
// A zombie counts as gone.
bool processAlive(int pid, uint64_t start);
// This process's start time in the form processAlive() compares.
uint64_t processStartTime(int pid);

}  // namespace common::libagent
