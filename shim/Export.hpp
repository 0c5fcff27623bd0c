// The shim is built with hidden visibility (CMakeLists.txt): only the
// functions it replaces in the program are exported, marked with this.
#pragma once

#define SIMSWIFT_SHIM_EXPORT __attribute__((visibility("default")))
