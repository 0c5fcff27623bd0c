// Whether the shim acts in this process. It is inert (every call passes
// through untouched) where no clock page is named (SIMSWIFT_CLOCK unset: not
// started by simswift) and in a debugger or tracer the program runs under
// (gdb, gdbserver, lldb, strace, ltrace, and the names in
// SIMSWIFT_SHIM_INERT), which keep the wall clock while their inferior, to
// which the environment passes on, reads the run's time (docs/shim.md, gdb).
#pragma once

namespace simswift::shim {

bool shimActive();
// The program's name for messages (its executable's file name).
const char* programName();

}  // namespace simswift::shim
