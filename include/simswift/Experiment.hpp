// A find-ball experiment file run from the library, as `simswift
// experiment FILE --out DIR --jobs N` runs it (every trial in its own
// process, byte-identical results whatever the jobs), returning the
// results table (results.csv).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "simswift/Errors.hpp"

namespace simswift::api {

struct ExperimentOptions {
  std::string out_dir;  // results folder; "" = results/<name>
  int jobs = 0;         // worker processes; 0 = the number of cores
  bool progress = false;  // a line per trial on stderr
};

struct ResultsTable {
  std::vector<std::string> columns;            // results.csv's header
  std::vector<std::vector<std::string>> rows;  // one per trial, as in results.csv
  std::string out_dir;                         // where report.md and the rest are
};

// Throws ConfigError (Errors.hpp: the file) or std::runtime_error (a trial's process or
// the results folder failed).
ResultsTable runExperiment(const std::string& file, const ExperimentOptions& options = {});

}  // namespace simswift::api

namespace simswift {
using api::runExperiment;
}  // namespace simswift
