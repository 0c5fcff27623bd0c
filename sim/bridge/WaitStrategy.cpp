#include "sim/bridge/WaitStrategy.hpp"

#include <errno.h>
#include <sched.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "sim/bridge/BodyHost.hpp"  // BridgeError

namespace simswift::bridge {

namespace {
// Polls before sleeping: up to this long, with pause instructions.
constexpr double kAnswerSpinSeconds = 300e-6;
inline void cpuRelax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

}  // namespace

timespec monotonicIn(double s) {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  const double whole = std::floor(s);
  t.tv_sec += static_cast<time_t>(whole);
  t.tv_nsec += static_cast<long>((s - whole) * 1e9);
  if (t.tv_nsec >= 1000000000L) {
    t.tv_sec += 1;
    t.tv_nsec -= 1000000000L;
  }
  return t;
}
bool before(const timespec& a, const timespec& b) {
  return a.tv_sec < b.tv_sec || (a.tv_sec == b.tv_sec && a.tv_nsec < b.tv_nsec);
}

bool waitUntil(sem_t* s, const timespec& deadline) {
  for (;;) {
    if (sem_clockwait(s, CLOCK_MONOTONIC, &deadline) == 0) return true;
    if (errno == ETIMEDOUT) return false;
    if (errno != EINTR) throw BridgeError(std::string("sem_clockwait: ") + std::strerror(errno));
  }
}

bool waitFor(const std::function<bool()>& done, const std::function<sem_t*()>& posted, double timeout_s) {
  const timespec spin_until = monotonicIn(std::min(kAnswerSpinSeconds, timeout_s));
  for (int spin = 0;; ++spin) {
    if (done()) return true;
    cpuRelax();
    if (spin % 64 == 63) {
      timespec now{};
      clock_gettime(CLOCK_MONOTONIC, &now);
      if (!before(now, spin_until)) break;
    }
  }
  const timespec deadline = monotonicIn(timeout_s);
  int polls = 0;
  for (;;) {
    if (done()) return true;
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    if (!before(now, deadline)) return done();
    if (sem_t* sem = posted()) {
      // Posted after publishing: sleep on it (bounded, so a missed post costs at most 1 ms).
      timespec t = monotonicIn(0.001);
      if (before(deadline, t)) t = deadline;
      sem_clockwait(sem, CLOCK_MONOTONIC, &t);
    } else if (++polls < 200) {
      sched_yield();
    } else {
      timespec nap{0, 20000};  // 20 us
      nanosleep(&nap, nullptr);
    }
  }
}

}  // namespace simswift::bridge
