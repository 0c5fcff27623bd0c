#include "shim/Timekeeper.hpp"

#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <climits>
#include <cstdio>
#include <mutex>

#include "shim/Clock.hpp"
#include "shim/Real.hpp"
#include "shim/Syscall.hpp"
#include "shim/Target.hpp"

namespace simswift::shim {

namespace {

constexpr int kSlots = 4096;  // alarms at once, per process

enum : int { Free = 0, Armed, Firing, Fired };

struct Slot {
  AlarmSpec spec;
  std::atomic<int> state{Free};
};

Slot g_slots[kSlots];
pthread_mutex_t g_lock = PTHREAD_MUTEX_INITIALIZER;  // guards spec of Armed slots
pthread_once_t g_once = PTHREAD_ONCE_INIT;

int (*realCondBroadcast())(pthread_cond_t*) {
  // glibc's 2.3.2 condvar ABI (Waits.cpp's realCond), else the default version
  // (an architecture whose glibc began later has only that one).
  static auto f = [] {
    void* s = dlvsym(RTLD_NEXT, "pthread_cond_broadcast", "GLIBC_2.3.2");
    return reinterpret_cast<int (*)(pthread_cond_t*)>(s != nullptr ? s : nextSymbol("pthread_cond_broadcast"));
  }();
  return f;
}

// False: not now (tried again next tick).
bool fire(Slot& s, int64_t now) {
  const AlarmSpec& a = s.spec;
  switch (a.kind) {
    case Alarm::CondBroadcast:
      // Under its mutex: the waiter holds it from registering until
      // pthread_cond_wait releases it, so the broadcast cannot come between.
      // Only tried: a thread that holds it while it waits for time itself
      // (through this thread) must not deadlock; the wait then ends on a
      // later tick, when the mutex is free (docs/shim.md).
      if (pthread_mutex_trylock(a.mutex) != 0) return false;
      realCondBroadcast()(a.cond);
      pthread_mutex_unlock(a.mutex);
      break;
    case Alarm::FutexWake:
      sys(SYS_futex, reinterpret_cast<long>(a.word), FUTEX_WAKE | a.futex_private, INT_MAX, 0, 0, 0);
      break;
    case Alarm::EventfdWrite: {
      const uint64_t one = 1;
      sys(SYS_write, a.fd, reinterpret_cast<long>(&one), sizeof one);
      break;
    }
    case Alarm::Timer: {
      uint64_t n = 1;
      if (a.period_ns > 0) n += static_cast<uint64_t>((now - a.deadline_ns) / a.period_ns);
      sys(SYS_write, a.fd, reinterpret_cast<long>(&n), sizeof n);
      break;
    }
  }
  return true;
}

void* keep(void*) {
  for (;;) {
    const uint32_t g = generation();
    const int64_t now = runNs();
    const bool over = runOver();
    for (Slot& s : g_slots) {
      if (s.state.load(std::memory_order_acquire) != Armed) continue;
      pthread_mutex_lock(&g_lock);
      int expected = Armed;
      const bool due = (s.spec.deadline_ns <= now || over) &&
                       s.state.compare_exchange_strong(expected, Firing, std::memory_order_acq_rel);
      pthread_mutex_unlock(&g_lock);
      if (!due) continue;
      if (!fire(s, now)) {
        s.state.store(Armed, std::memory_order_release);
        continue;
      }
      if (s.spec.kind == Alarm::Timer && s.spec.period_ns > 0 && !over) {
        const int64_t missed = (now - s.spec.deadline_ns) / s.spec.period_ns;
        s.spec.deadline_ns += (missed + 1) * s.spec.period_ns;
        s.state.store(Armed, std::memory_order_release);
      } else if (s.spec.kind == Alarm::FutexWake && !over) {
        // Woken again every tick until removed: a waiter that checked its
        // deadline just before this tick and then blocked missed the first
        // wake (it then ends one tick late; docs/shim.md).
        s.state.store(Armed, std::memory_order_release);
      } else {
        s.state.store(Fired, std::memory_order_release);
      }
    }
    if (over) {
      runOverNap();  // the run is over: alarms end as their time came (docs/shim.md)
      continue;
    }
    waitGeneration(g);
  }
  return nullptr;
}

void start() {
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
  pthread_attr_setstacksize(&attr, 64 * 1024);
  pthread_t t;
  if (pthread_create(&t, &attr, keep, nullptr) != 0) {
    std::fprintf(stderr, "simswift shim: %s: cannot start its timekeeper thread; timed waits cannot end\n",
                 programName());
    std::_Exit(70);
  }
  pthread_setname_np(t, "simswift-time");
  pthread_attr_destroy(&attr);
}

// After fork the child has no timekeeper (threads do not fork) and none of
// the parent's waits: start afresh.
void afterFork() {
  for (Slot& s : g_slots) s.state.store(Free, std::memory_order_relaxed);
  g_once = PTHREAD_ONCE_INIT;
  g_lock = PTHREAD_MUTEX_INITIALIZER;
}

__attribute__((constructor)) void registerFork() { pthread_atfork(nullptr, nullptr, afterFork); }

}  // namespace

int addAlarm(const AlarmSpec& spec) {
  pthread_once(&g_once, start);
  pthread_mutex_lock(&g_lock);
  for (int i = 0; i < kSlots; ++i) {
    if (g_slots[i].state.load(std::memory_order_relaxed) != Free) continue;
    g_slots[i].spec = spec;
    g_slots[i].state.store(Armed, std::memory_order_release);
    pthread_mutex_unlock(&g_lock);
    // The timekeeper may be asleep on this tick already: wake it is not
    // needed (a deadline in the past is checked by the caller first; one in
    // the future is only reached on a later tick).
    return i;
  }
  pthread_mutex_unlock(&g_lock);
  return -1;
}

bool removeAlarm(int h) {
  Slot& s = g_slots[h];
  for (;;) {
    pthread_mutex_lock(&g_lock);
    const int st = s.state.load(std::memory_order_acquire);
    if (st != Firing) {
      s.state.store(Free, std::memory_order_release);
      pthread_mutex_unlock(&g_lock);
      return st == Fired;
    }
    pthread_mutex_unlock(&g_lock);
    sched_yield();  // the timekeeper is inside fire() for it: microseconds
  }
}

bool alarmState(int h, int64_t* next) {
  pthread_mutex_lock(&g_lock);
  const int st = g_slots[h].state.load(std::memory_order_acquire);
  *next = g_slots[h].spec.deadline_ns;
  pthread_mutex_unlock(&g_lock);
  return st == Armed || st == Firing;
}

}  // namespace simswift::shim
