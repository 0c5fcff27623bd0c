// `simswift test ...`: the scenario tests' subcommand of simswift's command
// line (app/simswift.cpp; docs/testing.md), declared with CLI11 (app/cli).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/scenario_tests/TestBatch.hpp"

namespace CLI {
class App;
}

namespace simswift::scenario_tests {

// Declares `test FILE.yaml [options]` on `parent`; parsing `parent` fills
// this in. Not copied: the parser holds pointers into it.
class TestCommand {
 public:
  explicit TestCommand(CLI::App& parent);
  TestCommand(const TestCommand&) = delete;
  TestCommand& operator=(const TestCommand&) = delete;

  // After parsing: whether the command line chose `test`.
  bool chosen() const;
  // Runs it: 0 every test passes and none regressed; 1 a test fails, is
  // undecided or regressed, or a run could not run; 2 bad command line or
  // test file; 130 interrupted.
  int run() const;

 private:
  CLI::App* cmd_ = nullptr;
  std::string file_;
  TestOptions opt_;
  std::string shard_;
  std::string progress_;
  std::string record_;  // --record failures|all
  std::optional<uint64_t> seed_;
  std::string test_name_;
  std::optional<int> trial_;
  std::string overview_;
  std::vector<std::string> merge_dirs_;
  bool check_ = false;
};

}  // namespace simswift::scenario_tests
