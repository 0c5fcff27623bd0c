// Is a debugger attached to this process? The watchdog asks before it ends a
// run: a robot thread that sits at a gdb breakpoint is not a hung thread.
#pragma once

namespace simswift::runner {

// True when /proc/self/status names a tracer (TracerPid != 0): gdb, strace,
// rr. Cheap enough to ask each time a wait times out.
bool tracerAttached();

}  // namespace simswift::runner
