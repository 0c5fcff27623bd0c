// runExperiment (include/simswift/Experiment.hpp) over the batch runner.
#include "simswift/Experiment.hpp"

#include <fstream>
#include <sstream>

#include "app/api/ConfigErrors.hpp"
#include "app/experiment/Batch.hpp"
#include "app/experiment/BehaviourHooks.hpp"
#include "app/experiment/Csv.hpp"
#include "simswift/Simulation.hpp"

namespace simswift::api {

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
  if (std::getline(in, line)) t.columns = ex::splitCsv(line);
  while (std::getline(in, line))
    if (!line.empty()) t.rows.push_back(ex::splitCsv(line));
  return t;
}

}  // namespace simswift::api
