// Raw clock syscalls: a program (or a runtime) that calls clock_gettime,
// gettimeofday, time, nanosleep or clock_nanosleep with the `syscall`
// instruction bypasses libc and the vDSO, and would read the wall clock. A
// seccomp filter, installed when the shim loads, traps those five calls
// unless the shim made them (Syscall.hpp: sysClock), and the SIGSYS handler
// answers them in simulated time, as the shim's wrappers do (the program
// sees the call succeed: docs/shim.md). The filter needs no_new_privs (set
// here: a setuid program started from the robot's program no longer gains
// privileges). A process that already runs under a seccomp filter (one its
// parent's shim installed, inherited over fork and exec) adds none.
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <signal.h>
#include <stddef.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/time.h>
#include <ucontext.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "shim/Clock.hpp"
#include "shim/ClockCalls.hpp"
#include "shim/Export.hpp"
#include "shim/Real.hpp"
#include "shim/Syscall.hpp"
#include "shim/Target.hpp"

namespace simswift::shim {

namespace {

constexpr int kTrapped[] = {SYS_clock_gettime, SYS_gettimeofday, SYS_time, SYS_nanosleep, SYS_clock_nanosleep};

bool underSeccomp() {
  FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return false;
  char line[256];
  bool filtered = false;
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, "Seccomp:", 8) == 0) filtered = std::atoi(line + 8) == SECCOMP_MODE_FILTER;
  std::fclose(f);
  return filtered;
}

// The kernel's convention: -errno.
long answerSleep(int64_t deadline, timespec* rem) { return -sleepUntil(deadline, rem); }

// The trapped call's result, as the kernel's (-errno on failure).
long answer(long nr, greg_t* r) {
  const int saved = errno;
  long result = 0;
  switch (nr) {
    case SYS_clock_gettime:
      result = simswift_shim_clock_gettime(static_cast<clockid_t>(r[REG_RDI]),
                                           reinterpret_cast<timespec*>(r[REG_RSI])) == 0 ? 0 : -errno;
      break;
    case SYS_gettimeofday:
      result = simswift_shim_gettimeofday(reinterpret_cast<timeval*>(r[REG_RDI]), reinterpret_cast<void*>(r[REG_RSI]));
      break;
    case SYS_time:
      result = simswift_shim_time(reinterpret_cast<time_t*>(r[REG_RDI]));
      break;
    case SYS_nanosleep: {
      const auto* req = reinterpret_cast<const timespec*>(r[REG_RDI]);
      if (!req || req->tv_nsec < 0 || req->tv_nsec >= kNsPerS || req->tv_sec < 0) { result = -EINVAL; break; }
      result = answerSleep(runNs() + toNs(*req), reinterpret_cast<timespec*>(r[REG_RSI]));
      break;
    }
    case SYS_clock_nanosleep: {
      const auto clk = static_cast<clockid_t>(r[REG_RDI]);
      const int flags = static_cast<int>(r[REG_RSI]);
      const auto* req = reinterpret_cast<const timespec*>(r[REG_RDX]);
      int64_t offset = 0;
      if (!simulatedOffset(clk, &offset)) {
        result = sysClock(SYS_clock_nanosleep, clk, flags, r[REG_RDX], r[REG_R10]);
        break;
      }
      if (!req || req->tv_nsec < 0 || req->tv_nsec >= kNsPerS || req->tv_sec < 0) { result = -EINVAL; break; }
      result = (flags & TIMER_ABSTIME) ? answerSleep(toNs(*req) - offset, nullptr)
                                       : answerSleep(runNs() + toNs(*req), reinterpret_cast<timespec*>(r[REG_R10]));
      // clock_nanosleep returns the error as a positive number from libc,
      // but the raw call returns -errno like every other.
      break;
    }
    default:
      result = -ENOSYS;
  }
  errno = saved;
  return result;
}

void onSigsys(int, siginfo_t* info, void* context) {
  auto* uc = static_cast<ucontext_t*>(context);
  if (info->si_code != 1) return;  // SYS_SECCOMP (siginfo.h): only the filter's traps
  uc->uc_mcontext.gregs[REG_RAX] = answer(info->si_syscall, uc->uc_mcontext.gregs);
}

void install() {
  if (!clockActive()) return;
  // The handler in every process (exec resets it); the filter once per
  // process tree (it stays over fork and exec).
  struct sigaction sa {};
  sa.sa_sigaction = onSigsys;
  sa.sa_flags = SA_SIGINFO | SA_NODEFER;
  sigemptyset(&sa.sa_mask);
  real<int (*)(int, const struct sigaction*, struct sigaction*)>("sigaction")(SIGSYS, &sa, nullptr);
  if (underSeccomp()) return;
  constexpr unsigned kMagicLow = static_cast<uint32_t>(kAllowMagic);
  constexpr unsigned kMagicHigh = static_cast<uint32_t>(kAllowMagic >> 32);
  constexpr int n = sizeof kTrapped / sizeof kTrapped[0];
  // Offsets of seccomp_data's fields (linux/seccomp.h); args[5] in two
  // 32-bit halves (BPF loads 32 bits; x86-64 is little-endian).
  constexpr unsigned kArg5Low = offsetof(seccomp_data, args) + 5 * sizeof(uint64_t);
  sock_filter prog[11 + n] = {};
  int i = 0;
  prog[i++] = BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, arch));
  prog[i++] = BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, AUDIT_ARCH_X86_64, 1, 0);
  prog[i++] = BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW);
  prog[i++] = BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr));
  // One test per trapped call: jump to the magic check, else on.
  for (int k = 0; k < n; ++k)
    prog[i++] = BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, static_cast<unsigned>(kTrapped[k]),
                         static_cast<unsigned char>(n - k), 0);
  prog[i++] = BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW);  // not a clock call
  prog[i++] = BPF_STMT(BPF_LD | BPF_W | BPF_ABS, kArg5Low);  // a clock call: the shim's?
  prog[i++] = BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, kMagicLow, 0, 2);
  prog[i++] = BPF_STMT(BPF_LD | BPF_W | BPF_ABS, kArg5Low + 4);
  prog[i++] = BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, kMagicHigh, 1, 0);
  prog[i++] = BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_TRAP);
  prog[i++] = BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW);
  sock_fprog fprog{static_cast<unsigned short>(i), prog};
  if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0 ||
      prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &fprog, 0, 0) != 0) {
    std::fprintf(stderr, "simswift shim: %s: cannot install the seccomp filter for raw clock syscalls (%s); the "
                         "program is stopped rather than let such calls read the wall clock (docs/shim.md)\n",
                 programName(), std::strerror(errno));
    std::_Exit(70);
  }
}

}  // namespace

// When the library loads, before the program's main.
__attribute__((constructor)) static void installFilter() { install(); }

}  // namespace simswift::shim

// A program that takes SIGSYS for itself would take the shim's answers
// away: its handler is not installed (said once), the shim's stays.
extern "C" SIMSWIFT_SHIM_EXPORT int sigaction(int sig, const struct sigaction* act, struct sigaction* old) noexcept {
  using namespace simswift::shim;
  using Sigaction = int (*)(int, const struct sigaction*, struct sigaction*);
  static const Sigaction realSigaction = real<Sigaction>("sigaction");
  if (sig == SIGSYS && act != nullptr && clockActive()) {
    static bool said = false;
    if (!said) {
      said = true;
      std::fprintf(stderr, "simswift shim: %s: its SIGSYS handler is not installed: the shim answers raw clock "
                           "syscalls on SIGSYS (docs/shim.md)\n", programName());
    }
    return realSigaction(sig, nullptr, old);
  }
  return realSigaction(sig, act, old);
}
