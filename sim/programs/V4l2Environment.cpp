#include "sim/programs/V4l2Environment.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "common/v4l2/DeviceBlock.hpp"
#include "sim/programs/Errors.hpp"

namespace simswift::programs {

namespace fs = std::filesystem;

std::string shimLibrary() {
  constexpr const char* kName = "libsimswift-shim.so";
  if (const char* set = std::getenv("SIMSWIFT_SHIM"); set && *set) return set;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  for (const fs::path& dir : {exe.parent_path(), exe.parent_path().parent_path(),
                              exe.parent_path().parent_path() / SIMSWIFT_INSTALL_LIBDIR})
    if (access((dir / kName).c_str(), R_OK) == 0) return (dir / kName).string();
  return {};
}

void addV4l2Environment(std::vector<std::pair<std::string, std::string>>& env, const std::string& block,
                        const std::string& robot) {
  const std::string shim = shimLibrary();
  if (shim.empty())
    throw ProgramError("robot " + robot + ": its program's cameras need libsimswift-shim.so, found neither beside "
                           "simswift nor in its library folder (set SIMSWIFT_SHIM to its path, or v4l2: off)",
                       robot + ": no camera shim");
  std::string preload = shim;
  bool set = false;
  for (auto& [k, v] : env)
    if (k == "LD_PRELOAD") {
      if (!v.empty()) v = preload + ":" + v;
      else v = preload;
      set = true;
    }
  if (!set) {
    const char* own = std::getenv("LD_PRELOAD");
    env.emplace_back("LD_PRELOAD", own && *own ? preload + ":" + own : preload);
  }
  env.emplace_back(common::v4l2::kBlockVariable, block);
}

}  // namespace simswift::programs
