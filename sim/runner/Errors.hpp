// The errors a run ends with, by the runner's names: one type each, defined
// by the program side (sim/programs/Errors.hpp), which throws them too.
#pragma once

#include "sim/programs/Errors.hpp"

namespace simswift::runner {

using programs::ProgramError;
using programs::RunnerError;
using programs::WatchdogError;

}  // namespace simswift::runner
