// Helpers for the experiment tests: temporary folders, files, the simswift
// binary.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "sim/experiment/Batch.hpp"
#include "sim/experiment/BehaviourHooks.hpp"

namespace exptest {

inline std::string readAll(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void writeAll(const std::string& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

inline bool fileExists(const std::string& p) {
  struct stat st;
  return stat(p.c_str(), &st) == 0;
}

// A fresh folder under the build tree, named after the running test.
inline std::string freshDir(const std::string& tag) {
  const ::testing::TestInfo* t = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string d = std::string(SIMSWIFT_BINARY_DIR) + "/experiment_test_tmp/" + t->test_suite_name() + "_" +
                        t->name() + "_" + tag;
  const std::string cmd = "rm -rf '" + d + "' && mkdir -p '" + d + "'";
  if (std::system(cmd.c_str()) != 0) ADD_FAILURE() << "cannot create " << d;
  return d;
}

// Runs `e` into `dir` with simswift's hooks, quietly (shard k of n).
inline simswift::experiment::BatchOutcome runInto(const simswift::experiment::Experiment& e, const std::string& dir,
                                                  int jobs, int shard = 1, int shards = 1) {
  simswift::experiment::BatchOptions o;
  o.out_dir = dir;
  o.jobs = jobs;
  o.shard = shard;
  o.shards = shards;
  o.progress = simswift::experiment::BatchOptions::Progress::None;
  return simswift::experiment::runBatch(e, simswift::experiment::behaviourHooks(), o);
}

inline std::string simswiftBinary() { return std::string(SIMSWIFT_BINARY_DIR) + "/simswift"; }

// A tiny script-robot experiment: one robot walks toward ball position 1 and
// finds it after ~5 s; position 2 lies beside its path and is not found
// within the time limit. `trials` per position, `limit` s.
inline std::string tinyExperiment(int trials = 2, double limit = 7.0) {
  std::ostringstream s;
  s << "name: tiny\n"
       "seed: 11\n"
       "time_limit: "
    << limit
    << "\n"
       "trials_per_position: "
    << trials
    << "\n"
       "found: {distance: 0.3, sees: true}\n"
       "tracks: {every: 0.5}\n"
       "balls:\n"
       "  - {position: 1, x: 0.7, y: 0.0}\n"
       "  - {position: 2, x: 0.0, y: 1.5}\n"
       "setups:\n"
       "  - name: walker\n"
       "    behaviour: script\n"
       "    robots:\n"
       "      - {team: 19, player: 2, x: -0.5, y: 0.0, theta: 0.0,\n"
       "         actions: [{t: 0.3, action: walk, forward: 250}]}\n";
  return s.str();
}

}  // namespace exptest
