// The run's simulated time in the program: the robot's clock page
// (common/clock/ClockPage.hpp), mapped read only once, its header checked
// once; the clocks it gives and the waits that end on it. Everything the
// time wrappers (ClockCalls.cpp, Sleeps.cpp, Waits.cpp, ...) share.
#pragma once

#include <time.h>

#include <cstdint>

namespace simswift::shim {

constexpr int64_t kNsPerS = 1'000'000'000;

// True when the shim acts (Target.hpp) and the page is mapped. A page named
// but not usable (missing, wrong magic, version or size, a tick of 0 or
// less) ends the program with a message naming it (never the wall clock).
bool clockActive();
// The run's time (ns since t = 0), read once from the page: never less than
// a value this process read before (a page going backwards is reported once).
int64_t runNs();
// The clock `clk` in simulated time: its offset from the run's time (the
// REALTIME epoch, the MONOTONIC start); false: `clk` is not simulated (CPU
// time, another process's clock) and passes through.
bool simulatedOffset(clockid_t clk, int64_t* offset_ns);
int64_t tickNs();

inline int64_t toNs(const timespec& t) { return static_cast<int64_t>(t.tv_sec) * kNsPerS + t.tv_nsec; }
inline timespec toTimespec(int64_t ns) {
  timespec t;
  t.tv_sec = static_cast<time_t>(ns / kNsPerS);
  t.tv_nsec = static_cast<long>(ns % kNsPerS);
  if (t.tv_nsec < 0) t.tv_nsec += kNsPerS, t.tv_sec -= 1;
  return t;
}

enum class WaitEnd { Reached, Interrupted, RunOver };
// Blocks (a futex on the page's generation word, woken every tick) until
// the run's time reaches `deadline_run_ns`. Interrupted: a signal handler
// ran (EINTR). RunOver: the run ended before (the caller ends its wait as
// timed out, after kRunOverNapNs of wall clock so a loop does not spin).
// While the program has not answered its first packet (Starting), a wait
// ends at once: time starts with the run (docs/shim.md).
WaitEnd waitUntil(int64_t deadline_run_ns);
// A timed wait that finds the run Starting ends as timed out: this says so
// (once per process) and naps kRunOverNapNs of wall clock, and never blocks
// in simulated time. Not waitUntil: the run may start during the call, and a
// wait in simulated time then would not see what the caller waits on (a
// semaphore posted for the next tick: the run would wait for a thread that
// waits for the run; seen as "motion thread did not answer ... (tick 2)").
void startingWait();
// A sleep until `deadline_run_ns` (shim/Sleeps.cpp): 0, or EINTR with `rem`
// (if given) the time left; the libc wrappers and the trapped syscalls share it.
int sleepUntil(int64_t deadline_run_ns, timespec* rem);
constexpr int64_t kRunOverNapNs = 10'000'000;
void runOverNap();
// The generation word (for waits that also watch other things: Waits.cpp).
uint32_t generation();
// Blocks until the generation is no longer `seen` (or a signal): false on EINTR.
bool waitGeneration(uint32_t seen);
bool runStarting();
bool runOver();

}  // namespace simswift::shim
