// What a program started against a run (launched, or `simswift attach`)
// gets so that libsimswift-shim.so (shim/, docs/shim.md) is loaded into it:
// LD_PRELOAD and the variables the shim reads. The one place the shim's
// environment is made; each part of the shim adds its variables here.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace simswift::programs {

struct ShimSettings {
  std::string clock_page;  // the robot's clock page (common/clock/ClockPage.hpp)
  std::string v4l2_block;  // its cameras' device block (common/v4l2/DeviceBlock.hpp); "" = no V4L2 cameras
};

// The built or installed shim: $SIMSWIFT_SHIM_LIBRARY if set, else
// libsimswift-shim.so beside this executable, one folder up (a test binary in
// build/tests) or in <prefix>/<libdir> of an installed one. "" if none is
// found.
std::string shimLibraryPath();

// The environment a program is started with against a run, launched or
// `simswift attach`ed: `env` (its own variables) with the shim's set over
// them: LD_PRELOAD with the shim first (before env's own LD_PRELOAD, else
// simswift's), LD_AUDIT with the early SIGSYS handler
// (shim/early/Early.cpp), SIMSWIFT_CLOCK and, with cameras, SIMSWIFT_V4L2.
// Throws std::runtime_error naming `robot` if `command` (argv[0]) cannot
// take the shim (ProgramBinary.hpp: never run on the wall clock) or either
// library is not found.
using Environment = std::vector<std::pair<std::string, std::string>>;
Environment shimLaunchEnvironment(const std::string& robot, const std::string& command, const ShimSettings& s,
                                  Environment env);

}  // namespace simswift::programs
