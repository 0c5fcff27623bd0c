// The clocks a program reads, in simulated time (Clock.hpp): the functions
// libc's wrappers, the vDSO's patched entry points (Vdso.cpp) and the SIGSYS
// handler (Seccomp.cpp) all answer with. They make no libc call: what
// passes through (a CPU-time clock) is the shim's own raw syscall.
#pragma once

#include <sys/time.h>
#include <time.h>

namespace simswift::shim {

extern "C" int simswift_shim_clock_gettime(clockid_t clk, timespec* ts);
extern "C" int simswift_shim_gettimeofday(timeval* tv, void* tz);
extern "C" time_t simswift_shim_time(time_t* t);

}  // namespace simswift::shim
