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

// The variables to add to the program's environment: LD_PRELOAD with the
// shim first (before `preload_before`, what the program would otherwise get:
// the launch's own LD_PRELOAD or simswift's), LD_AUDIT with the early
// SIGSYS handler (shim/early/Early.cpp), SIMSWIFT_CLOCK and, with cameras,
// SIMSWIFT_V4L2. Throws std::runtime_error naming `robot` if either library
// is not found.
std::vector<std::pair<std::string, std::string>> shimEnvironment(const std::string& robot, const ShimSettings& s,
                                                                 const std::string& preload_before);

}  // namespace simswift::programs
