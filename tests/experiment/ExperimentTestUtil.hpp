// Helpers for the experiment tests: temporary folders, files, the simswift
// binary.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "app/experiment/Batch.hpp"
#include "app/experiment/BehaviourHooks.hpp"
#include "tests/support/ConfigErrors.hpp"

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

// /proc/<pid>/stat's state letter and parent pid; false if there is no such process.
inline bool procStat(pid_t pid, char* state, pid_t* ppid) {
  const std::string stat = readAll("/proc/" + std::to_string(pid) + "/stat");
  const size_t paren = stat.rfind(')');  // the command may hold spaces and parentheses
  if (paren == std::string::npos) return false;
  std::istringstream in(stat.substr(paren + 1));
  long parent = 0;
  in >> *state >> parent;
  *ppid = static_cast<pid_t>(parent);
  return static_cast<bool>(in);
}

// Alive: there, and not a zombie (an orphan's zombie waits for a reaper that
// a container's pid 1 may never be).
inline bool processAlive(pid_t pid) {
  char state = 0;
  pid_t ppid = 0;
  return procStat(pid, &state, &ppid) && state != 'Z';
}

// The live processes whose parent is `pid`.
inline std::vector<pid_t> childrenOf(pid_t pid) {
  std::vector<pid_t> out;
  for (const auto& p : std::filesystem::directory_iterator("/proc")) {
    const std::string name = p.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    char state = 0;
    pid_t ppid = 0;
    const pid_t child = static_cast<pid_t>(std::stol(name));
    if (procStat(child, &state, &ppid) && ppid == pid && state != 'Z') out.push_back(child);
  }
  return out;
}

// Waits until every process in `pids` has ended, up to `seconds` (wall
// clock); returns those still alive.
inline std::vector<pid_t> stillAliveAfter(const std::vector<pid_t>& pids, double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  std::vector<pid_t> alive;
  do {
    alive.clear();
    for (pid_t p : pids)
      if (processAlive(p)) alive.push_back(p);
    if (alive.empty()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  } while (std::chrono::steady_clock::now() < deadline);
  return alive;
}

// The ConfigError's message for `text` as an experiment file, or "" if it loads.
inline std::string experimentError(const std::string& text) {
  return simswift::testing::configError([&] { simswift::experiment::Experiment::parse(text, "bad.yaml"); });
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
