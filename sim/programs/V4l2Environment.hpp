// What a launched program's environment needs for its cameras as V4L2
// devices (docs/porting.md section 3): the shim preloaded (LD_PRELOAD) and
// the name of its robot's device block (common/v4l2/DeviceBlock.hpp). Kept
// apart so that it merges with the simulated clock's part of the shim's
// environment.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace simswift::programs {

// libsimswift-shim.so: $SIMSWIFT_SHIM if set, else beside this executable,
// in its parent folder (a build tree's tests/) or in the installed library
// folder; empty if none is found.
std::string shimLibrary();

// Adds to `env` (a launched program's, already filled) the shim first in
// LD_PRELOAD (before what `env` or simswift's own environment preload) and
// SIMSWIFT_V4L2=`block`. Throws ProgramError naming the robot if the shim
// is not found.
void addV4l2Environment(std::vector<std::pair<std::string, std::string>>& env, const std::string& block,
                        const std::string& robot);

}  // namespace simswift::programs
