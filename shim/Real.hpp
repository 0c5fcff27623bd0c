// What libsimswift-shim.so (this folder) is: a library simswift preloads
// (LD_PRELOAD) into a launched team program, so that the unchanged binary
// meets the robot's world rather than the machine's: the run's simulated
// clock, the NAO's cameras as V4L2 devices (docs/porting.md). It is loaded
// into someone else's process, so it is lean: no simswift library is linked
// in (headers of common/ only), no exceptions leave it, nothing is
// allocated before the program's main unless it must be.
//
// This header: the libc functions the shim wraps, looked up once with
// dlsym(RTLD_NEXT) so a wrapper can call what it replaced.
#pragma once

#include <dlfcn.h>

namespace simswift::shim {

// The next definition of `name` after the shim (libc's, normally); aborts
// with a message naming it when there is none (a libc without it).
void* nextSymbol(const char* name);

template <typename F>
F real(const char* name) {
  return reinterpret_cast<F>(nextSymbol(name));
}

}  // namespace simswift::shim
