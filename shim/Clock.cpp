#include "shim/Clock.hpp"

#include <fcntl.h>
#include <linux/futex.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "common/clock/ClockPage.hpp"
#include "shim/Syscall.hpp"
#include "shim/Target.hpp"

namespace simswift::shim {

namespace cc = common::clock;

namespace {

// The header's values, copied once when mapped (never re-read).
struct Mapped {
  const cc::ClockLayout* page = nullptr;
  int64_t tick_ns = 0;
  int64_t epoch_ns = 0;
};

[[noreturn]] void refuse(const char* page, const char* why) {
  std::fprintf(stderr, "simswift shim: %s: clock page %s: %s; the program is stopped rather than run on the wall "
                       "clock (docs/shim.md)\n", programName(), page, why);
  std::_Exit(70);
}

Mapped mapPage() {
  Mapped m;
  if (!shimActive()) return m;
  const char* name = std::getenv(cc::kPageEnv);
  const int fd = shm_open(name, O_RDONLY | O_CLOEXEC, 0);
  if (fd < 0) refuse(name, std::strerror(errno));
  struct stat st {};
  if (fstat(fd, &st) != 0 || st.st_size < static_cast<off_t>(sizeof(cc::ClockLayout)))
    refuse(name, "smaller than a clock page (not simswift's, or from another version)");
  void* p = mmap(nullptr, sizeof(cc::ClockLayout), PROT_READ, MAP_SHARED, fd, 0);
  close(fd);
  if (p == MAP_FAILED) refuse(name, std::strerror(errno));
  const auto* page = static_cast<const cc::ClockLayout*>(p);
  const uint32_t magic = page->magic;
  std::atomic_thread_fence(std::memory_order_acquire);
  if (magic != cc::kMagic) refuse(name, "no clock page magic (not simswift's, or not written yet)");
  if (page->version != cc::kVersion) refuse(name, "another version of the clock page (a different simswift)");
  if (page->size != sizeof(cc::ClockLayout)) refuse(name, "a clock page of another size");
  const int64_t tick = page->tick_ns;
  if (tick <= 0 || tick > 10 * kNsPerS) refuse(name, "a tick outside (0, 10 s]");
  m.page = page;
  m.tick_ns = tick;
  m.epoch_ns = page->realtime_epoch_ns;
  return m;
}

const Mapped& mapped() {
  static const Mapped m = mapPage();
  return m;
}

std::atomic<int64_t> g_last_ns{0};
std::atomic<bool> g_backwards_reported{false};
std::atomic<bool> g_starting_reported{false};

uint32_t* generationWord() {
  return reinterpret_cast<uint32_t*>(const_cast<std::atomic<uint32_t>*>(&mapped().page->generation));
}

}  // namespace

// Mapped when the library loads, before the program's main (a page that is
// not usable stops the program here, with its message).
__attribute__((constructor)) static void mapAtLoad() { (void)mapped(); }

bool clockActive() { return mapped().page != nullptr; }
int64_t tickNs() { return mapped().tick_ns; }

int64_t runNs() {
  const int64_t n = mapped().page->now_ns.load(std::memory_order_acquire);
  int64_t last = g_last_ns.load(std::memory_order_relaxed);
  while (n > last && !g_last_ns.compare_exchange_weak(last, n, std::memory_order_relaxed)) {
  }
  if (n >= last) return n;
  if (!g_backwards_reported.exchange(true))
    std::fprintf(stderr, "simswift shim: %s: the clock page went back from %lld to %lld ns; keeping %lld\n",
                 programName(), static_cast<long long>(last), static_cast<long long>(n),
                 static_cast<long long>(last));
  return last;
}

bool simulatedOffset(clockid_t clk, int64_t* offset_ns) {
  switch (clk) {
    case CLOCK_REALTIME:
    case CLOCK_REALTIME_COARSE:
    case CLOCK_REALTIME_ALARM:
      *offset_ns = mapped().epoch_ns;
      return true;
    case CLOCK_TAI:
      *offset_ns = mapped().epoch_ns + cc::kTaiOffsetNs;
      return true;
    case CLOCK_MONOTONIC:
    case CLOCK_MONOTONIC_RAW:
    case CLOCK_MONOTONIC_COARSE:
    case CLOCK_BOOTTIME:
    case CLOCK_BOOTTIME_ALARM:
      *offset_ns = cc::kMonotonicStartNs;
      return true;
    default:
      return false;  // CPU-time clocks, other processes' clocks
  }
}

uint32_t generation() { return mapped().page->generation.load(std::memory_order_acquire); }
bool runStarting() {
  return mapped().page->state.load(std::memory_order_acquire) == static_cast<uint32_t>(cc::RunState::Starting);
}
bool runOver() {
  return mapped().page->state.load(std::memory_order_acquire) == static_cast<uint32_t>(cc::RunState::Ended);
}

bool waitGeneration(uint32_t seen) {
  // Shared (not FUTEX_PRIVATE): simswift wakes it from its own process.
  const long r = sys(SYS_futex, reinterpret_cast<long>(generationWord()), FUTEX_WAIT, seen, 0, 0, 0);
  return r != -EINTR;
}

void runOverNap() {
  const timespec t = toTimespec(kRunOverNapNs);
  sysClock(SYS_nanosleep, reinterpret_cast<long>(&t), 0);
}

void startingWait() {
  if (!g_starting_reported.exchange(true))
    std::fprintf(stderr, "simswift shim: %s waits for time before answering its first packet: simulated time "
                         "starts with the run, so waits before it end at once (docs/shim.md)\n", programName());
  // A short real nap: a program that retries its timed wait in a loop
  // (libagent's liveness check) must not spin a core until the run starts.
  runOverNap();
}

WaitEnd waitUntil(int64_t deadline_run_ns) {
  for (;;) {
    const uint32_t g = generation();
    if (runNs() >= deadline_run_ns) return WaitEnd::Reached;
    if (runOver()) return WaitEnd::RunOver;
    if (runStarting()) {
      startingWait();
      return WaitEnd::Reached;
    }
    if (!waitGeneration(g)) return WaitEnd::Interrupted;
  }
}

}  // namespace simswift::shim
