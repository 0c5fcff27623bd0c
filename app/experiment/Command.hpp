// `simswift experiment ...`: the experiment's subcommand of simswift's
// command line (app/simswift.cpp), declared with CLI11 (app/cli).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/experiment/Batch.hpp"
#include "app/experiment/TrialHooks.hpp"

namespace CLI {
class App;
}

namespace simswift::experiment {

// `experiment FILE.yaml [options]` and `experiment merge DIR... --out DIR`.
// Declares both on `parent`; parsing `parent` fills this in. Not copied:
// the parser holds pointers into it.
class ExperimentCommand {
 public:
  explicit ExperimentCommand(CLI::App& parent);
  ExperimentCommand(const ExperimentCommand&) = delete;
  ExperimentCommand& operator=(const ExperimentCommand&) = delete;

  // After parsing: whether the command line chose `experiment`.
  bool chosen() const;
  // Runs it: 0 done, 1 trial or I/O failure, 2 bad command line or
  // experiment file, 130 interrupted.
  int run(const TrialHooks& hooks) const;

 private:
  CLI::App* cmd_ = nullptr;
  CLI::App* merge_ = nullptr;
  std::string file_;
  std::string out_;
  std::vector<std::string> merge_dirs_;
  std::string merge_out_;
  BatchOptions opt_;
  std::string shard_;
  std::string progress_;
  std::optional<int> trial_;
  std::vector<int> record_;  // --record: trial indices
  bool check_ = false;
};

}  // namespace simswift::experiment
