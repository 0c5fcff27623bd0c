#include "sim/programs/ShimEnvironment.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "common/clock/ClockPage.hpp"
#include "common/v4l2/DeviceBlock.hpp"
#include "sim/programs/ProgramBinary.hpp"

#ifndef SIMSWIFT_INSTALL_LIBDIR
#define SIMSWIFT_INSTALL_LIBDIR "lib"
#endif

namespace simswift::programs {

namespace fs = std::filesystem;

namespace {
constexpr const char* kShimFile = "libsimswift-shim.so";
// Beside it: the SIGSYS handler from load time (shim/early/Early.cpp).
constexpr const char* kEarlyFile = "libsimswift-shim-early.so";
}

std::string shimLibraryPath() {
  if (const char* e = std::getenv("SIMSWIFT_SHIM_LIBRARY"); e && *e) return e;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  const fs::path dir = exe.parent_path();
  for (const fs::path& candidate :
       {dir / kShimFile, dir.parent_path() / kShimFile, dir.parent_path() / SIMSWIFT_INSTALL_LIBDIR / kShimFile})
    if (access(candidate.c_str(), R_OK) == 0) return candidate.lexically_normal().string();
  return "";
}

Environment shimLaunchEnvironment(const std::string& robot, const std::string& command, const ShimSettings& s,
                                  Environment env) {
  const std::string exe = findExecutable(command);
  if (const std::string why = exe.empty() ? "" : shimRefusal(exe); !why.empty())
    throw std::runtime_error("robot " + robot + ": its program '" + command + "' is " + why);
  const std::string shim = shimLibraryPath();
  if (shim.empty())
    throw std::runtime_error("robot " + robot + ": " + kShimFile +
                             " (the simulated clock, docs/shim.md) was not found beside simswift, one folder up or "
                             "in its lib folder; build the simswift_shim target or set SIMSWIFT_SHIM_LIBRARY");
  const std::string early = (fs::path(shim).parent_path() / kEarlyFile).string();
  if (access(early.c_str(), R_OK) != 0)
    throw std::runtime_error("robot " + robot + ": " + kEarlyFile + " is not beside " + shim +
                             " (docs/shim.md: a program exec'd under the clock filter needs it); build the "
                             "simswift_shim_early target");
  std::string preload;
  for (const auto& [k, v] : env)
    if (k == "LD_PRELOAD") preload = v;
  if (const char* p = std::getenv("LD_PRELOAD"); p && preload.empty()) preload = p;
  Environment shim_env;
  shim_env.emplace_back("LD_PRELOAD", preload.empty() ? shim : shim + ":" + preload);
  shim_env.emplace_back("LD_AUDIT", early);
  shim_env.emplace_back(common::clock::kPageEnv, s.clock_page);
  if (!s.v4l2_block.empty()) shim_env.emplace_back(common::v4l2::kBlockVariable, s.v4l2_block);
  for (auto& kv : shim_env) {
    env.erase(std::remove_if(env.begin(), env.end(), [&](const auto& x) { return x.first == kv.first; }), env.end());
    env.push_back(std::move(kv));
  }
  return env;
}

}  // namespace simswift::programs
