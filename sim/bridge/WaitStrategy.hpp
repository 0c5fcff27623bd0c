// How the simulator waits for a robot program's answer (wall clock: only
// how long to wait for another thread or process, never simulation time).
// The Motion thread usually answers within a few hundred microseconds of the
// tick: the wait looks for the answer that long (pause instructions) before
// it sleeps, which saves a futex sleep and wake-up (a fifth of a walking
// robot's wall time was the kernel's, measured with perf). Then it sleeps on
// the program's `answered` semaphore if the program posts one (a
// simswift-aware program), else polls with sched_yield, then 20 us naps (an
// unchanged libagent program, which only sets an index).
#pragma once

#include <semaphore.h>
#include <time.h>

#include <functional>

namespace simswift::bridge {

// Absolute CLOCK_MONOTONIC time `s` seconds from now.
timespec monotonicIn(double s);
bool before(const timespec& a, const timespec& b);
// Waits on `s` until the absolute CLOCK_MONOTONIC `deadline`; false on timeout.
bool waitUntil(sem_t* s, const timespec& deadline);
// Waits until done() (see above); posted() is the program's semaphore, or
// null while it posts none. False if done() is still false after timeout_s.
bool waitFor(const std::function<bool()>& done, const std::function<sem_t*()>& posted, double timeout_s);

}  // namespace simswift::bridge
