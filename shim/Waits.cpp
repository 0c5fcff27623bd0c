// Timed waits on condition variables and semaphores, in simulated time:
// pthread_cond_timedwait (the condvar's clock: REALTIME, or MONOTONIC set
// with pthread_condattr_setclock), pthread_cond_clockwait, sem_timedwait
// (REALTIME), sem_clockwait. The wait blocks untimed; the timekeeper
// (Timekeeper.hpp) wakes it when the run reaches the deadline.
#include <linux/futex.h>
#include <pthread.h>
#include <semaphore.h>
#include <sys/syscall.h>

#include <atomic>
#include <cerrno>
#include <cstdio>

#include "shim/Clock.hpp"
#include "shim/Export.hpp"
#include "shim/Real.hpp"
#include "shim/Syscall.hpp"
#include "shim/Target.hpp"
#include "shim/Timekeeper.hpp"

using namespace simswift::shim;

namespace {

using CondWait = int (*)(pthread_cond_t*, pthread_mutex_t*);
using CondTimedWait = int (*)(pthread_cond_t*, pthread_mutex_t*, const timespec*);
using CondClockWait = int (*)(pthread_cond_t*, pthread_mutex_t*, clockid_t, const timespec*);

// glibc exports the condvar functions in two versions (the old LinuxThreads
// ABI and 2.3.2's); programs link the new one.
template <typename F>
F realCond(const char* name) {
  static_assert(sizeof(F) == sizeof(void*), "a function pointer");
  void* f = dlvsym(RTLD_NEXT, name, "GLIBC_2.3.2");
  if (f == nullptr) f = nextSymbol(name);
  return reinterpret_cast<F>(f);
}

void tableFull(const char* what) {
  std::fprintf(stderr, "simswift shim: %s: more than 4096 timed waits at once (%s); this one waits untimed\n",
               programName(), what);
}

// glibc (2.25+, nptl/pthread_cond_common.c): bit 1 of __wrefs is the
// condvar's clock (0 REALTIME, 1 MONOTONIC).
clockid_t condClock(const pthread_cond_t* c) {
  return (c->__data.__wrefs & 2) ? CLOCK_MONOTONIC : CLOCK_REALTIME;
}

int condWaitUntil(pthread_cond_t* c, pthread_mutex_t* m, clockid_t clk, const timespec* abstime) {
  int64_t offset = 0;
  if (abstime == nullptr || abstime->tv_nsec < 0 || abstime->tv_nsec >= kNsPerS) return EINVAL;
  simulatedOffset(clk, &offset);
  const int64_t deadline = toNs(*abstime) - offset;
  if (runNs() >= deadline) return ETIMEDOUT;
  if (runStarting()) {
    startingWait();  // the mutex stays held, as a timed-out wait returns it
    return ETIMEDOUT;
  }
  if (runOver()) {
    runOverNap();
    return ETIMEDOUT;
  }
  AlarmSpec a{Alarm::CondBroadcast, deadline};
  a.cond = c;
  a.mutex = m;
  const int h = addAlarm(a);
  if (h < 0) tableFull("pthread_cond_timedwait");
  // We hold m: the timekeeper's broadcast (under m) comes after we block.
  const int r = realCond<CondWait>("pthread_cond_wait")(c, m);
  if (h >= 0) removeAlarm(h);
  if (r != 0) return r;
  // Woken by the program or by the deadline (a wakeup at the deadline is a
  // timeout; before it, a wakeup as POSIX allows spurious ones).
  return runNs() >= deadline ? ETIMEDOUT : 0;
}

// glibc's semaphore (nptl/semaphoreP.h, 64-bit): the value in the low 32
// bits of `data`, the number of waiters in the high 32; sem_post wakes the
// value word's futex when there are waiters. `priv` is glibc's LLL_PRIVATE
// (0) or LLL_SHARED (128): the futex op's flag is FUTEX_PRIVATE_FLAG ^ priv
// (lowlevellock-futex.h's __lll_private_flag).
struct GlibcSem {
  std::atomic<uint64_t> data;
  int priv;
  int pad;
};
static_assert(sizeof(GlibcSem) <= sizeof(sem_t), "glibc's new semaphore");
constexpr uint64_t kWaiter = uint64_t{1} << 32;

int semWaitUntil(sem_t* sem, clockid_t clk, const timespec* abstime) {
  if (abstime == nullptr || abstime->tv_nsec < 0 || abstime->tv_nsec >= kNsPerS) {
    errno = EINVAL;
    return -1;
  }
  int64_t offset = 0;
  simulatedOffset(clk, &offset);
  const int64_t deadline = toNs(*abstime) - offset;
  auto* s = reinterpret_cast<GlibcSem*>(sem);
  auto tryTake = [&](bool registered) {
    uint64_t d = s->data.load(std::memory_order_relaxed);
    while ((d & 0xffffffffu) > 0)
      if (s->data.compare_exchange_weak(d, d - 1 - (registered ? kWaiter : 0), std::memory_order_acquire))
        return true;
    return false;
  };
  if (tryTake(false)) return 0;
  auto timedOut = [] {
    errno = ETIMEDOUT;
    return -1;
  };
  if (runNs() >= deadline) return timedOut();
  if (runStarting()) {
    startingWait();
    return timedOut();
  }
  if (runOver()) {
    runOverNap();
    return timedOut();
  }
  uint32_t* word = reinterpret_cast<uint32_t*>(&s->data);  // the low half (x86-64 is little-endian)
  AlarmSpec a{Alarm::FutexWake, deadline};
  a.word = word;
  const int flag = FUTEX_PRIVATE_FLAG ^ s->priv;
  a.futex_private = flag;
  const int h = addAlarm(a);
  if (h < 0) tableFull("sem_timedwait");
  s->data.fetch_add(kWaiter, std::memory_order_relaxed);
  int result = 0;
  for (;;) {
    if (tryTake(true)) break;
    if (runNs() >= deadline || runOver()) {
      s->data.fetch_sub(kWaiter, std::memory_order_relaxed);
      errno = ETIMEDOUT, result = -1;
      break;
    }
    const long r = sys(SYS_futex, reinterpret_cast<long>(word), FUTEX_WAIT | flag, 0, 0, 0, 0);
    if (r == -EINTR) {
      s->data.fetch_sub(kWaiter, std::memory_order_relaxed);
      errno = EINTR, result = -1;
      break;
    }
  }
  if (h >= 0) removeAlarm(h);
  return result;
}

}  // namespace

extern "C" SIMSWIFT_SHIM_EXPORT int pthread_cond_timedwait(pthread_cond_t* c, pthread_mutex_t* m,
                                                          const struct timespec* abstime) {
  if (!clockActive()) return realCond<CondTimedWait>("pthread_cond_timedwait")(c, m, abstime);
  return condWaitUntil(c, m, condClock(c), abstime);
}

extern "C" SIMSWIFT_SHIM_EXPORT int pthread_cond_clockwait(pthread_cond_t* c, pthread_mutex_t* m, clockid_t clk,
                                                          const struct timespec* abstime) {
  int64_t offset = 0;
  if (!clockActive() || (clk != CLOCK_REALTIME && clk != CLOCK_MONOTONIC) || !simulatedOffset(clk, &offset))
    return real<CondClockWait>("pthread_cond_clockwait")(c, m, clk, abstime);
  return condWaitUntil(c, m, clk, abstime);
}

extern "C" SIMSWIFT_SHIM_EXPORT int sem_timedwait(sem_t* sem, const struct timespec* abstime) {
  if (!clockActive()) return real<int (*)(sem_t*, const timespec*)>("sem_timedwait")(sem, abstime);
  return semWaitUntil(sem, CLOCK_REALTIME, abstime);
}

extern "C" SIMSWIFT_SHIM_EXPORT int sem_clockwait(sem_t* sem, clockid_t clk, const struct timespec* abstime) {
  if (!clockActive() || (clk != CLOCK_REALTIME && clk != CLOCK_MONOTONIC))
    return real<int (*)(sem_t*, clockid_t, const timespec*)>("sem_clockwait")(sem, clk, abstime);
  return semWaitUntil(sem, clk, abstime);
}
