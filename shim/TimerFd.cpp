// timerfd in simulated time: timerfd_create on a simulated clock gives an
// eventfd (read gives the expirations since the last read, as a timerfd
// does; poll, select and epoll see it readable); timerfd_settime arms the
// timekeeper (Timekeeper.hpp), which adds the expirations at the ticks that
// reach them; timerfd_gettime answers from it. The alarm writes through the
// shim's own duplicate of the fd, so a program that closes its timerfd
// (and the number is reused) is never written to.
#include <fcntl.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <cerrno>
#include <mutex>

#include "shim/Clock.hpp"
#include "shim/Export.hpp"
#include "shim/Real.hpp"
#include "shim/Timekeeper.hpp"

using namespace simswift::shim;

namespace {

constexpr int kMaxFd = 4096;  // timerfds above it stay on the kernel's (wall) clock: said once

struct Timer {
  bool ours = false;
  clockid_t clk = CLOCK_MONOTONIC;
  int dup = -1;      // the shim's duplicate, written by the alarm
  int alarm = -1;    // armed alarm, or -1
  int64_t interval = 0;
};
Timer g_timers[kMaxFd];
std::mutex g_mutex;

void disarm(Timer& t) {
  if (t.alarm >= 0) removeAlarm(t.alarm);
  t.alarm = -1;
  // Expirations not read yet are dropped, as when a timerfd is re-armed.
  pollfd p{t.dup, POLLIN, 0};
  uint64_t n;
  while (real<int (*)(pollfd*, nfds_t, int)>("poll")(&p, 1, 0) == 1 && (p.revents & POLLIN) &&
         read(t.dup, &n, sizeof n) == sizeof n) {
  }
}

itimerspec current(const Timer& t) {
  itimerspec v{};
  v.it_interval = toTimespec(t.interval);
  int64_t next = 0;
  if (t.alarm >= 0 && alarmState(t.alarm, &next)) {
    const int64_t left = next - runNs();
    v.it_value = toTimespec(left > 0 ? left : 1);  // armed: never reads 0 (that is "disarmed")
  }
  return v;
}

}  // namespace

extern "C" SIMSWIFT_SHIM_EXPORT int timerfd_create(int clk, int flags) noexcept {
  int64_t offset = 0;
  if (!clockActive() || !simulatedOffset(clk, &offset))
    return real<int (*)(int, int)>("timerfd_create")(clk, flags);
  if (flags & ~(TFD_NONBLOCK | TFD_CLOEXEC)) {
    errno = EINVAL;
    return -1;
  }
  // TFD_NONBLOCK and TFD_CLOEXEC are O_NONBLOCK and O_CLOEXEC, as EFD_'s are.
  const int fd = eventfd(0, flags);
  if (fd < 0) return -1;
  if (fd >= kMaxFd) {
    close(fd);
    errno = EMFILE;
    return -1;
  }
  std::lock_guard<std::mutex> lock(g_mutex);
  Timer& t = g_timers[fd];
  if (t.ours) {  // the number of a timerfd the program closed: its leftovers go
    if (t.alarm >= 0) removeAlarm(t.alarm);
    close(t.dup);
  }
  t = Timer{};
  t.ours = true;
  t.clk = clk;
  t.dup = fcntl(fd, F_DUPFD_CLOEXEC, kMaxFd);
  if (t.dup < 0) {
    t.ours = false;
    close(fd);
    return -1;
  }
  return fd;
}

extern "C" SIMSWIFT_SHIM_EXPORT int timerfd_settime(int fd, int flags, const struct itimerspec* nv,
                                                    struct itimerspec* old) noexcept {
  using Settime = int (*)(int, int, const itimerspec*, itimerspec*);
  if (fd < 0 || fd >= kMaxFd || !g_timers[fd].ours) return real<Settime>("timerfd_settime")(fd, flags, nv, old);
  if (nv == nullptr || nv->it_value.tv_nsec < 0 || nv->it_value.tv_nsec >= kNsPerS || nv->it_interval.tv_nsec < 0 ||
      nv->it_interval.tv_nsec >= kNsPerS) {
    errno = EINVAL;
    return -1;
  }
  std::lock_guard<std::mutex> lock(g_mutex);
  Timer& t = g_timers[fd];
  if (old) *old = current(t);
  disarm(t);
  t.interval = toNs(nv->it_interval);
  const int64_t value = toNs(nv->it_value);
  if (value == 0) return 0;  // disarmed
  int64_t offset = 0;
  simulatedOffset(t.clk, &offset);
  AlarmSpec a{Alarm::Timer, (flags & TFD_TIMER_ABSTIME) ? value - offset : runNs() + value};
  a.fd = t.dup;
  a.period_ns = t.interval;
  t.alarm = addAlarm(a);
  if (t.alarm < 0) {
    errno = ENOMEM;
    return -1;
  }
  return 0;
}

extern "C" SIMSWIFT_SHIM_EXPORT int timerfd_gettime(int fd, struct itimerspec* cur) noexcept {
  if (fd < 0 || fd >= kMaxFd || !g_timers[fd].ours)
    return real<int (*)(int, itimerspec*)>("timerfd_gettime")(fd, cur);
  std::lock_guard<std::mutex> lock(g_mutex);
  *cur = current(g_timers[fd]);
  return 0;
}
