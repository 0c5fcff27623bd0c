// The shim's own system calls, made without libc (so neither libc's
// wrappers, which the shim replaces, nor errno are involved). The clock
// calls the seccomp filter traps (Seccomp.cpp) are let through when made
// here: sysClock puts kAllowMagic in the sixth argument register, which
// those calls do not use (the kernel ignores it) and the filter checks. An
// argument rather than an address, so a filter inherited over exec still
// recognises the new program's shim.
#pragma once

namespace simswift::shim {

// The raw syscall: its result, or -errno (errno untouched).
extern "C" long simswift_shim_syscall(long nr, long a1, long a2, long a3, long a4, long a5, long a6);

constexpr unsigned long kAllowMagic = 0x5357494654434c4bUL;  // "SWIFTCLK"

inline long sys(long nr, long a1 = 0, long a2 = 0, long a3 = 0, long a4 = 0, long a5 = 0, long a6 = 0) {
  return simswift_shim_syscall(nr, a1, a2, a3, a4, a5, a6);
}
// A clock syscall (clock_gettime, nanosleep, ...) the filter lets through.
inline long sysClock(long nr, long a1 = 0, long a2 = 0, long a3 = 0, long a4 = 0) {
  return simswift_shim_syscall(nr, a1, a2, a3, a4, 0, static_cast<long>(kAllowMagic));
}

}  // namespace simswift::shim
