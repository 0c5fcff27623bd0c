// The timeouts of poll, ppoll, select, pselect, epoll_wait and epoll_pwait,
// in simulated time. The program's fds are waited on as they are (real
// fds, also the shim's cameras); beside them the thread's own eventfd,
// which the timekeeper (Timekeeper.hpp) makes readable when the run reaches
// the deadline. No polling: the thread blocks until an fd is ready or the
// deadline's tick.
#include <poll.h>
#include <signal.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/select.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "shim/Clock.hpp"
#include "shim/Export.hpp"
#include "shim/Real.hpp"
#include "shim/Target.hpp"
#include "shim/Timekeeper.hpp"

using namespace simswift::shim;

namespace {

using Ppoll = int (*)(pollfd*, nfds_t, const timespec*, const sigset_t*);
using Pselect = int (*)(int, fd_set*, fd_set*, fd_set*, const timespec*, const sigset_t*);
using EpollPwait = int (*)(int, epoll_event*, int, int, const sigset_t*);

Ppoll realPpoll() {
  static const Ppoll f = real<Ppoll>("ppoll");
  return f;
}

// The calling thread's eventfd (kept for the thread's life; its counter
// drained before each use). A forked child makes its own: the parent's
// timekeeper still writes the inherited one.
int threadEventfd() {
  thread_local int fd = -1;
  thread_local pid_t owner = 0;
  if (fd >= 0 && owner != getpid()) {
    close(fd);
    fd = -1;
  }
  if (fd < 0) {
    owner = getpid();
    fd = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
    if (fd < 0) {
      std::fprintf(stderr, "simswift shim: %s: eventfd: %s; a timed poll cannot end\n", programName(),
                   std::strerror(errno));
      std::_Exit(70);
    }
  }
  uint64_t n;
  while (read(fd, &n, sizeof n) == sizeof n) {
  }
  return fd;
}

// A timed wait in progress: the deadline and the alarm that marks it.
class Deadline {
 public:
  // `timeout_ns` >= 0.
  explicit Deadline(int64_t timeout_ns) : deadline_(runNs() + timeout_ns) {}
  ~Deadline() {
    if (handle_ >= 0) removeAlarm(handle_);
  }
  // The eventfd to wait on beside the program's fds; -1 when the wait must
  // end at once (reached, before the run's first answer, the run over).
  int arm() {
    if (runNs() >= deadline_) return -1;
    if (runStarting()) {
      startingWait();
      return -1;
    }
    if (runOver()) {
      runOverNap();
      return -1;
    }
    const int fd = threadEventfd();
    AlarmSpec a{Alarm::EventfdWrite, deadline_};
    a.fd = fd;
    handle_ = addAlarm(a);
    if (handle_ < 0) std::fprintf(stderr, "simswift shim: %s: too many timed waits at once\n", programName());
    return fd;
  }
  bool reached() const { return runNs() >= deadline_ || runOver(); }
  int64_t left() const {
    const int64_t l = deadline_ - runNs();
    return l > 0 ? l : 0;
  }

 private:
  int64_t deadline_;
  int handle_ = -1;
};

// Before the run's first answer (Starting) time has not started, but the
// program's other threads may be about to give it its first answer: a wait
// on fds waits for them in slices of wall clock (kRunOverNapNs) until they
// are ready, the run starts (then the simulated deadline counts from there)
// or its timeout has passed as wall clock. `once(slice)` waits one slice:
// non-zero (ready, or an error) ends the wait with that result.
template <typename Once>
int whileStarting(int64_t timeout_ns, Once once, bool* started) {
  for (int64_t waited = 0; runStarting() && waited < timeout_ns; waited += kRunOverNapNs) {
    const int r = once(toTimespec(std::min(kRunOverNapNs, timeout_ns - waited)));
    if (r != 0) return r;
  }
  *started = !runStarting();
  return 0;
}

int pollUntil(pollfd* fds, nfds_t n, int64_t timeout_ns, const sigset_t* mask) {
  if (n > 0 && runStarting()) {
    bool started = false;
    const int r = whileStarting(timeout_ns, [&](timespec s) { return realPpoll()(fds, n, &s, mask); }, &started);
    if (r != 0 || !started) return r;
  }
  Deadline d(timeout_ns);
  const int efd = d.arm();
  if (efd < 0) {
    const timespec zero{0, 0};
    return realPpoll()(fds, n, &zero, mask);
  }
  std::vector<pollfd> all(fds, fds + n);
  all.push_back({efd, POLLIN, 0});
  for (;;) {
    const int r = realPpoll()(all.data(), all.size(), nullptr, mask);
    if (r < 0) return r;
    const int user = r - (all.back().revents ? 1 : 0);
    if (user > 0 || d.reached()) {
      for (nfds_t i = 0; i < n; ++i) fds[i].revents = all[i].revents;
      return user;
    }
    uint64_t v;
    (void)!read(efd, &v, sizeof v);
  }
}

int selectUntil(int nfds, fd_set* rd, fd_set* wr, fd_set* ex, int64_t timeout_ns, const sigset_t* mask,
                int64_t* left) {
  static const Pselect realPselect = real<Pselect>("pselect");
  Deadline d(timeout_ns);
  const int efd = d.arm();
  if (efd < 0 || efd >= FD_SETSIZE) {
    const timespec zero{0, 0};
    *left = 0;
    return realPselect(nfds, rd, wr, ex, &zero, mask);
  }
  fd_set empty;
  FD_ZERO(&empty);
  const fd_set r0 = rd ? *rd : empty, w0 = wr ? *wr : empty, e0 = ex ? *ex : empty;
  for (;;) {
    fd_set r = r0, w = w0, e = e0;
    FD_SET(efd, &r);
    const int n = realPselect(nfds > efd ? nfds : efd + 1, &r, wr ? &w : nullptr, ex ? &e : nullptr, nullptr, mask);
    if (n < 0) return n;
    const bool alarm = FD_ISSET(efd, &r);
    FD_CLR(efd, &r);
    if (!FD_ISSET(efd, &r0) && alarm && n == 1 && !d.reached()) {
      uint64_t v;
      (void)!read(efd, &v, sizeof v);
      continue;
    }
    const int user = n - (alarm ? 1 : 0);
    if (user > 0 || d.reached()) {
      if (rd) *rd = r;
      if (wr) *wr = w;
      if (ex) *ex = e;
      *left = d.left();
      return user;
    }
  }
}

int epollUntil(int epfd, epoll_event* events, int max, int64_t timeout_ns, const sigset_t* mask) {
  static const EpollPwait realEpoll = real<EpollPwait>("epoll_pwait");
  if (runStarting()) {
    bool started = false;
    const int r = whileStarting(
        timeout_ns,
        [&](timespec s) { return realEpoll(epfd, events, max, static_cast<int>((s.tv_nsec + 999'999) / 1'000'000), mask); },
        &started);
    if (r != 0 || !started) return r;
  }
  Deadline d(timeout_ns);
  const int efd = d.arm();
  if (efd < 0) return realEpoll(epfd, events, max, 0, mask);
  pollfd two[2] = {{epfd, POLLIN, 0}, {efd, POLLIN, 0}};
  for (;;) {
    const int r = realPpoll()(two, 2, nullptr, mask);
    if (r < 0) return r;
    if (two[0].revents) {
      const int n = realEpoll(epfd, events, max, 0, nullptr);
      if (n != 0) return n;
    }
    if (d.reached()) return 0;
    if (two[1].revents) {
      uint64_t v;
      (void)!read(efd, &v, sizeof v);
    }
  }
}

int64_t msToNs(int ms) { return static_cast<int64_t>(ms) * 1'000'000; }
bool validTimespec(const timespec* t) { return t->tv_sec >= 0 && t->tv_nsec >= 0 && t->tv_nsec < kNsPerS; }

}  // namespace

extern "C" SIMSWIFT_SHIM_EXPORT int poll(struct pollfd* fds, nfds_t n, int timeout_ms) {
  if (!clockActive() || timeout_ms <= 0) return real<int (*)(pollfd*, nfds_t, int)>("poll")(fds, n, timeout_ms);
  return pollUntil(fds, n, msToNs(timeout_ms), nullptr);
}

extern "C" SIMSWIFT_SHIM_EXPORT int ppoll(struct pollfd* fds, nfds_t n, const struct timespec* tmo,
                                         const sigset_t* mask) {
  if (!clockActive() || tmo == nullptr || (tmo->tv_sec == 0 && tmo->tv_nsec == 0)) return realPpoll()(fds, n, tmo, mask);
  if (!validTimespec(tmo)) {
    errno = EINVAL;
    return -1;
  }
  return pollUntil(fds, n, toNs(*tmo), mask);
}

extern "C" SIMSWIFT_SHIM_EXPORT int select(int nfds, fd_set* rd, fd_set* wr, fd_set* ex, struct timeval* tv) {
  using Select = int (*)(int, fd_set*, fd_set*, fd_set*, timeval*);
  if (!clockActive() || tv == nullptr || (tv->tv_sec == 0 && tv->tv_usec == 0))
    return real<Select>("select")(nfds, rd, wr, ex, tv);
  if (tv->tv_sec < 0 || tv->tv_usec < 0 || tv->tv_usec >= 1'000'000) {
    errno = EINVAL;
    return -1;
  }
  int64_t left = 0;
  const int r = selectUntil(nfds, rd, wr, ex, static_cast<int64_t>(tv->tv_sec) * kNsPerS + tv->tv_usec * 1000,
                            nullptr, &left);
  // Linux writes the time not slept back (select(2)).
  tv->tv_sec = static_cast<time_t>(left / kNsPerS);
  tv->tv_usec = static_cast<suseconds_t>((left % kNsPerS) / 1000);
  return r;
}

extern "C" SIMSWIFT_SHIM_EXPORT int pselect(int nfds, fd_set* rd, fd_set* wr, fd_set* ex,
                                           const struct timespec* tmo, const sigset_t* mask) {
  if (!clockActive() || tmo == nullptr || (tmo->tv_sec == 0 && tmo->tv_nsec == 0))
    return real<Pselect>("pselect")(nfds, rd, wr, ex, tmo, mask);
  if (!validTimespec(tmo)) {
    errno = EINVAL;
    return -1;
  }
  int64_t left = 0;
  return selectUntil(nfds, rd, wr, ex, toNs(*tmo), mask, &left);
}

extern "C" SIMSWIFT_SHIM_EXPORT int epoll_wait(int epfd, struct epoll_event* events, int max, int timeout_ms) {
  if (!clockActive() || timeout_ms <= 0)
    return real<int (*)(int, epoll_event*, int, int)>("epoll_wait")(epfd, events, max, timeout_ms);
  return epollUntil(epfd, events, max, msToNs(timeout_ms), nullptr);
}

extern "C" SIMSWIFT_SHIM_EXPORT int epoll_pwait(int epfd, struct epoll_event* events, int max, int timeout_ms,
                                               const sigset_t* mask) {
  if (!clockActive() || timeout_ms <= 0)
    return real<EpollPwait>("epoll_pwait")(epfd, events, max, timeout_ms, mask);
  return epollUntil(epfd, events, max, msToNs(timeout_ms), mask);
}
