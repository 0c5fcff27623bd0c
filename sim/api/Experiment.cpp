// runExperiment (include/simswift/Experiment.hpp) over the batch runner.
#include "simswift/Experiment.hpp"

#include <fstream>
#include <regex>
#include <sstream>

#include "sim/api/ConfigErrors.hpp"
#include "sim/experiment/Batch.hpp"
#include "sim/experiment/BehaviourHooks.hpp"
#include "simswift/Simulation.hpp"

namespace simswift::api {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',') out.emplace_back();
    else if (c != '\r') out.back() += c;
  }
  return out;
}

}  // namespace

ResultsTable runExperiment(const std::string& file, const ExperimentOptions& options) {
  namespace ex = simswift::experiment;
  ex::Experiment e;
  try {
    e = ex::Experiment::loadFile(file);
    ex::checkBehaviours(e, ex::behaviourHooks());
  } catch (const simswift::ConfigError& err) {
    throw configError(err);
  }
  ex::BatchOptions opt;
  opt.out_dir = options.out_dir.empty() ? "results/" + e.name : options.out_dir;
  opt.jobs = options.jobs;
  opt.progress = options.progress ? ex::BatchOptions::Progress::Lines : ex::BatchOptions::Progress::None;
  const ex::BatchOutcome o = ex::runBatch(e, ex::behaviourHooks(), opt);
  if (!o.assembled) throw std::runtime_error(file + ": " + o.message);
  ResultsTable t;
  t.out_dir = opt.out_dir;
  std::ifstream in(opt.out_dir + "/results.csv");
  std::string line;
  if (std::getline(in, line)) t.columns = split(line);
  while (std::getline(in, line))
    if (!line.empty()) t.rows.push_back(split(line));
  return t;
}

}  // namespace simswift::api
