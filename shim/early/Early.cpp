// libsimswift-shim-early.so: named in LD_AUDIT beside libsimswift-shim.so
// (sim/programs/ShimEnvironment.cpp), so the dynamic loader runs it before
// any of the program's code. Why: the seccomp filter that traps raw clock
// syscalls (shim/Seccomp.cpp) stays over exec, but the SIGSYS handler that
// answers them does not; a program exec'd by a launched program (a team's
// binary started by its wrapper script) runs under the filter with no
// handler until the shim's constructor, and a raw clock call in that window
// would kill it with SIGSYS. Sanitizer runtimes make such calls (ASan reads
// the clock in the executable's .preinit_array, before any library's
// constructor). This handler covers the window: it makes the trapped call
// itself, let through by the filter, so such a start-up read sees the
// machine's clock (docs/shim.md, "What is covered"). The shim's constructor
// then installs its own handler, which answers in simulated time.
#include <link.h>
#include <signal.h>
#include <ucontext.h>

#include "shim/Syscall.hpp"

namespace {

void passThrough(int, siginfo_t* info, void* context) {
  if (info->si_code != 1) return;  // SYS_SECCOMP (siginfo.h): only the filter's traps
  greg_t* r = static_cast<ucontext_t*>(context)->uc_mcontext.gregs;
  r[REG_RAX] = simswift::shim::sysClock(info->si_syscall, r[REG_RDI], r[REG_RSI], r[REG_RDX], r[REG_R10]);
}

}  // namespace

// rtld-audit(7): called first, when the loader loads this library. It asks
// for no other audit call (none is exported), so binding is not slowed.
extern "C" __attribute__((visibility("default"))) unsigned int la_version(unsigned int version) {
  struct sigaction sa {};
  sa.sa_sigaction = passThrough;
  sa.sa_flags = SA_SIGINFO | SA_NODEFER;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGSYS, &sa, nullptr);
  return version;  // LAV_CURRENT or older: whatever this loader speaks
}
