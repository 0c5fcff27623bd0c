// The clock page: one shared memory object per robot that simswift writes
// and a launched (or attached) program's shim (shim/) reads, so the
// program's clocks read the run's simulated time (issue 44, docs/shim.md).
//
// simswift (sim/programs/ClockPage) creates it before the program starts,
// writes the header once and, every tick, stores `now_ns` and then bumps
// `generation` and wakes every futex waiter on it. It writes tick k's time
// before tick k's sensors are posted (Runner stage 6), so a program that
// reads tick k's packet reads tick k's time. The shim maps it read only,
// checks the header once and reads each field once per use.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

namespace common::clock {

// The environment variable naming the page (a POSIX shm name, "/..."), set
// for a launched program and by `simswift attach`.
constexpr const char* kPageEnv = "SIMSWIFT_CLOCK";
// Extra executable names (':'-separated) in which the shim stays inert
// (besides the debuggers it knows: shim/Target.cpp).
constexpr const char* kInertEnv = "SIMSWIFT_SHIM_INERT";

constexpr uint32_t kMagic = 0x4b4c4353;  // "SCLK" little-endian
constexpr uint32_t kVersion = 2;  // 2: the run's pid and the robot's view (attach)

// Where the program's clocks start. MONOTONIC and BOOTTIME read
// kMonotonicStartNs + the run's time, as if the robot had booted a minute
// before the run (never 0: some programs take 0 for "unset").
constexpr int64_t kMonotonicStartNs = 60'000'000'000;
// REALTIME's default epoch (a scenario's clock_epoch overrides it):
// 2025-07-15T00:00:00Z: a fixed date keeps runs reproducible.
constexpr int64_t kDefaultRealtimeEpochNs = 1'752'537'600'000'000'000;
// TAI is REALTIME + 37 s (the leap seconds since 1972, IERS Bulletin C).
constexpr int64_t kTaiOffsetNs = 37'000'000'000;

// flags: the run serves this robot's cameras as V4L2 devices in the block
// named by the robot (common/v4l2/DeviceBlock.hpp blockName): set for an
// external robot's page, so `simswift attach` knows to hand the block to its
// program (and to wait for it), and knows when there is none to wait for.
constexpr uint32_t kFlagV4l2ByRobot = 1u;
// The robot's body is LoLA's socket (a V6); without it, libagent's block (a
// V5): `simswift attach --team T --player P` waits for the socket only then.
constexpr uint32_t kFlagLola = 2u;
// The run holds a view for the robot (sim/programs/ProgramView.hpp, as a
// launched program's: PID and network namespaces, /tmp, files): `view_pid`
// is the pid of the init holding its namespaces, `view_folder` the run's
// folder of it; `simswift attach` starts its command in it.
constexpr uint32_t kFlagView = 4u;

enum class RunState : uint32_t {
  Starting = 0,  // the program has not answered its first packet yet
  Running = 1,   // time moves with the run's ticks
  Ended = 2,     // the run is over: time stands; waits end (docs/shim.md)
};

struct ClockLayout {
  // Written once before the program starts.
  uint32_t magic;
  uint32_t version;
  uint32_t size;             // sizeof(ClockLayout)
  uint32_t flags;            // kFlag* bits: what else the run serves this robot (attach reads it)
  int64_t tick_ns;           // the body's cycle: 10 ms (libagent), 12 ms (LoLA)
  int64_t realtime_epoch_ns; // REALTIME at the run's t = 0, ns since 1970
  // Written every tick.
  std::atomic<int64_t> now_ns;        // the run's simulated time: tick k * tick_ns
  std::atomic<uint32_t> generation;   // futex word: +1 after every write of now_ns or state
  std::atomic<uint32_t> state;        // RunState
  // Written once before the program starts (version 2).
  int32_t run_pid;           // simswift's pid (attach: is the run alive)
  int32_t view_pid;          // with kFlagView: the view's init (in simswift's PID namespace)
  char view_folder[512];     // with kFlagView: the run's folder of the view, NUL-terminated
};
static_assert(std::atomic<int64_t>::is_always_lock_free, "the page is shared between processes");
static_assert(std::atomic<uint32_t>::is_always_lock_free, "the page is shared between processes");
static_assert(sizeof(std::atomic<uint32_t>) == 4, "generation is a futex word");

// The robot's page name: "/simswift-clock-t19p1" (the robot's tag, as its
// libagent objects and LoLA socket are named by it).
inline std::string pageName(const std::string& robot_tag) { return "/simswift-clock-" + robot_tag; }

}  // namespace common::clock
