// The batch's progress on stderr: a bar redrawn in place (a terminal), a
// line per trial (a log), or nothing; failures always get a line.
#pragma once

#include <chrono>
#include <string>

#include "app/experiment/Trial.hpp"

namespace simswift::experiment {

struct ProgressLine {
  bool bar = false, lines = true;
  int total = 0, done = 0;  // trials of the shard; done includes those done before this run
  int failed = 0, ran = 0;  // by this run
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();

  void trial(const TrialResult& r);  // a find-ball trial finished: its outcome and the ETA
  void step(const std::string& what); // any trial finished: `what` happened, and the ETA
  void fail(int trial, const std::string& why);
  void end();  // ends the bar's line
};

// "1h05m" or "3m07s"; "?" for a negative or non-finite duration (s).
std::string formatDuration(double s);

}  // namespace simswift::experiment
