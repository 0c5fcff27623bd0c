#include "shim/ClockCalls.hpp"

#include <sys/syscall.h>

#include <cerrno>

#include "shim/Clock.hpp"
#include "shim/Export.hpp"
#include "shim/Real.hpp"
#include "shim/Syscall.hpp"

namespace simswift::shim {

namespace {
int result(long r) {
  if (r < 0) {
    errno = static_cast<int>(-r);
    return -1;
  }
  return static_cast<int>(r);
}
}  // namespace

extern "C" int simswift_shim_clock_gettime(clockid_t clk, timespec* ts) {
  int64_t offset = 0;
  if (!simulatedOffset(clk, &offset))
    return result(sysClock(SYS_clock_gettime, clk, reinterpret_cast<long>(ts)));
  if (ts == nullptr) {
    errno = EFAULT;
    return -1;
  }
  *ts = toTimespec(offset + runNs());
  return 0;
}

extern "C" int simswift_shim_gettimeofday(timeval* tv, void* tz) {
  if (tz != nullptr) {
    // The robot's zone is UTC (struct timezone is obsolete; Linux fills zeros for UTC).
    auto* z = static_cast<int*>(tz);
    z[0] = 0;
    z[1] = 0;
  }
  if (tv != nullptr) {
    int64_t offset = 0;
    simulatedOffset(CLOCK_REALTIME, &offset);
    const int64_t ns = offset + runNs();
    tv->tv_sec = static_cast<time_t>(ns / kNsPerS);
    tv->tv_usec = static_cast<suseconds_t>((ns % kNsPerS) / 1000);
  }
  return 0;
}

extern "C" time_t simswift_shim_time(time_t* t) {
  int64_t offset = 0;
  simulatedOffset(CLOCK_REALTIME, &offset);
  const time_t s = static_cast<time_t>((offset + runNs()) / kNsPerS);
  if (t != nullptr) *t = s;
  return s;
}

}  // namespace simswift::shim

// libc's entry points (what a program calls, also std::chrono's clocks).
using namespace simswift::shim;

extern "C" SIMSWIFT_SHIM_EXPORT int clock_gettime(clockid_t clk, struct timespec* ts) noexcept {
  if (!clockActive()) return real<int (*)(clockid_t, timespec*)>("clock_gettime")(clk, ts);
  return simswift_shim_clock_gettime(clk, ts);
}

extern "C" SIMSWIFT_SHIM_EXPORT int gettimeofday(struct timeval* tv, void* tz) noexcept {
  if (!clockActive()) return real<int (*)(timeval*, void*)>("gettimeofday")(tv, tz);
  return simswift_shim_gettimeofday(tv, tz);
}

extern "C" SIMSWIFT_SHIM_EXPORT time_t time(time_t* t) noexcept {
  if (!clockActive()) return real<time_t (*)(time_t*)>("time")(t);
  return simswift_shim_time(t);
}

// C11's clock (TIME_UTC is REALTIME).
extern "C" SIMSWIFT_SHIM_EXPORT int timespec_get(struct timespec* ts, int base) noexcept {
  if (!clockActive() || base != TIME_UTC) return real<int (*)(timespec*, int)>("timespec_get")(ts, base);
  return simswift_shim_clock_gettime(CLOCK_REALTIME, ts) == 0 ? base : 0;
}
