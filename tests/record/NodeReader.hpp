// The MCAP project's own reader (@mcap/core from npm) under node, for the
// recording tests: installed once into the build tree at test time
// (build/npm-mcap, under a lock so parallel tests share it), then
// tests/record/mcap_check.cjs prints what it read as JSON.
#pragma once

#include <cstdlib>
#include <string>

#include "tests/support/Shell.hpp"

namespace simswift::testing {

// Empty if the reader is ready; otherwise why not (the caller skips, or
// fails when SIMSWIFT_REQUIRE_NODE is set, as CI does).
inline std::string prepareMcapReader(std::string& modules) {
  const std::string dir = std::string(SIMSWIFT_BINARY_DIR) + "/npm-mcap";
  modules = dir + "/node_modules";
  if (shell("command -v node && command -v npm").code != 0) return "node or npm not installed (scripts/install-deps.sh)";
  if (shell("test -f " + modules + "/@mcap/core/package.json").code == 0) return "";
  const ShellResult r = shell("mkdir -p " + dir + " && cd " + dir + " && flock " + dir +
                              ".lock sh -c 'test -f node_modules/@mcap/core/package.json || "
                              "npm install --no-audit --no-fund --no-save --prefix . @mcap/core@2.2.2'");
  if (r.code != 0) return "npm install @mcap/core failed (no registry?): " + r.output;
  return "";
}

inline bool nodeRequired() { return std::getenv("SIMSWIFT_REQUIRE_NODE") != nullptr; }

}  // namespace simswift::testing
