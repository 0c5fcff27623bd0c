// The sleeps, in simulated time: nanosleep, clock_nanosleep (relative and
// TIMER_ABSTIME), usleep, sleep. Each ends at the first tick at or after
// the simulated time asked for (Clock.hpp: waitUntil), never before.
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>

#include "shim/Clock.hpp"
#include "shim/Export.hpp"
#include "shim/Real.hpp"

using namespace simswift::shim;

namespace simswift::shim {

// 0, or the error number (clock_nanosleep's convention); `rem` for an
// interrupted relative sleep.
int sleepUntil(int64_t deadline, timespec* rem) {
  switch (waitUntil(deadline)) {
    case WaitEnd::Reached:
      return 0;
    case WaitEnd::RunOver:
      runOverNap();
      return 0;
    case WaitEnd::Interrupted:
      if (rem != nullptr) {
        const int64_t left = deadline - runNs();
        *rem = toTimespec(left > 0 ? left : 0);
      }
      return EINTR;
  }
  return 0;
}

}  // namespace simswift::shim

namespace {

bool validRequest(const timespec* req) {
  return req != nullptr && req->tv_nsec >= 0 && req->tv_nsec < kNsPerS && req->tv_sec >= 0;
}

}  // namespace

extern "C" SIMSWIFT_SHIM_EXPORT int clock_nanosleep(clockid_t clk, int flags, const struct timespec* req, struct timespec* rem) {
  int64_t offset = 0;
  if (!clockActive() || !simulatedOffset(clk, &offset))
    return real<int (*)(clockid_t, int, const timespec*, timespec*)>("clock_nanosleep")(clk, flags, req, rem);
  if (!validRequest(req)) return EINVAL;
  if (flags & TIMER_ABSTIME) return sleepUntil(toNs(*req) - offset, nullptr);
  return sleepUntil(runNs() + toNs(*req), rem);
}

extern "C" SIMSWIFT_SHIM_EXPORT int nanosleep(const struct timespec* req, struct timespec* rem) {
  if (!clockActive()) return real<int (*)(const timespec*, timespec*)>("nanosleep")(req, rem);
  if (!validRequest(req)) {
    errno = EINVAL;
    return -1;
  }
  const int e = sleepUntil(runNs() + toNs(*req), rem);
  if (e != 0) {
    errno = e;
    return -1;
  }
  return 0;
}

extern "C" SIMSWIFT_SHIM_EXPORT int usleep(useconds_t us) {
  if (!clockActive()) return real<int (*)(useconds_t)>("usleep")(us);
  const timespec req = toTimespec(static_cast<int64_t>(us) * 1000);
  return nanosleep(&req, nullptr);
}

extern "C" SIMSWIFT_SHIM_EXPORT unsigned int sleep(unsigned int s) {
  if (!clockActive()) return real<unsigned (*)(unsigned)>("sleep")(s);
  const timespec req = toTimespec(static_cast<int64_t>(s) * kNsPerS);
  timespec rem{};
  if (nanosleep(&req, &rem) == 0) return 0;
  return static_cast<unsigned>(rem.tv_sec + (rem.tv_nsec > 0 ? 1 : 0));
}
