// What a run reports: the one-line summary and a line per robot. Filled by
// Runner::stats(); formatting lives here so the Runner only runs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace simswift::runner {

struct RunStats {
  double sim_s = 0;          // simulated seconds run
  double wall_s = 0;         // wall-clock seconds (reporting only)
  double real_time_factor = 0;
  int64_t ticks = 0;
  int falls = 0;             // FallDetector falls, summed over robots
  int blowups = 0;           // world resets after a numerical blow-up
  int64_t nan_commands = 0;  // summed over robots
  int64_t clamped_angles = 0;
  int64_t clamped_stiffness = 0;
  int64_t skipped_cycles = 0;
  uint64_t hash = 0;         // World::stateHash() at the end
  // The UDP GameController (game: {udp: on}): packets sent, and return
  // packets heard per robot (team: SPL number); wall-clock dependent,
  // reporting only.
  int64_t gc_udp_sent = 0;
  int64_t gc_udp_failed = 0;  // sends that failed
  struct GcReturns {
    int team = 0, player = 0;
    int64_t packets = 0;
  };
  std::vector<GcReturns> gc_returns;

  // Where each robot ended (field frame: m, rad), in scenario order.
  struct RobotEnd {
    int team = 0, player = 0;
    double x = 0, y = 0, theta = 0;  // torso position and heading
    int falls = 0;
    bool down = false;  // on the ground at the end (fallen and not yet back up)
    int contact_falls = 0;  // of falls, those right after touching another robot (FallDetector)
  };
  std::vector<RobotEnd> robots;

  std::string summary() const;       // the one-line summary
  std::string robotLines() const;    // one line per robot: "  t0p1: x .. m  y .. m  theta .. rad  falls N  up|down"
};


// The run's number formats, shared by the summary and the runner's messages:
// printf-style `f` applied to v, and a state hash as 16 hex digits.
std::string formatNumber(const char* f, double v);
std::string hashHex(uint64_t hash);

}  // namespace simswift::runner
