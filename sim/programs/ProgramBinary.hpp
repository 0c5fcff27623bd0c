// What simswift checks of a program's executable before it starts it
// against a run: the shim (docs/shim.md) reaches only a dynamically linked
// program, so a static one is refused rather than run on the wall clock.
#pragma once

#include <string>

namespace simswift::programs {

// The file execvp would run for `command` (a path with '/' as is, else the
// first executable of that name on PATH); "" if none.
std::string findExecutable(const std::string& command);

// "" if `path` can take the shim: an ELF with a program interpreter
// (PT_INTERP), or a script ("#!": its interpreter is checked when it runs,
// by the shim in it). Otherwise why not: "a statically linked executable
// (no PT_INTERP): ...".
std::string shimRefusal(const std::string& path);

}  // namespace simswift::programs
