#include "sim/runner/Tracer.hpp"

#include <fstream>
#include <string>

namespace simswift::runner {

bool tracerAttached() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("TracerPid:", 0) == 0) return std::stol(line.substr(10)) != 0;
  return false;  // not Linux /proc: no way to tell
}

}  // namespace simswift::runner
