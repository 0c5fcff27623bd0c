#include "sim/experiment/ResultsFolder.hpp"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>

#include <dirent.h>
#include <unistd.h>

#include "sim/experiment/Batch.hpp"
#include "sim/experiment/Files.hpp"

namespace simswift::experiment {

std::string trialFile(const std::string& dir, int trial, const std::string& suffix) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "trial_%06d", trial);
  return dir + "/trials/" + buf + suffix;
}

void claimFolder(const Experiment& e, const std::string& dir) {
  makeDirs(dir + "/trials");
  const std::string copy = dir + "/experiment.yaml";
  if (exists(copy)) {
    if (readFile(copy) != e.text)
      throw BatchError(dir + " holds results of a different experiment file (" + copy +
                       " differs from " + e.source + "): choose another --out or remove the folder");
  } else {
    writeAtomic(copy, e.text);
  }
  // Temporary files of processes that died mid-write.
  if (DIR* d = opendir((dir + "/trials").c_str())) {
    while (dirent* ent = readdir(d)) {
      const std::string n = ent->d_name;
      const size_t k = n.find(".tmp");
      if (k == std::string::npos) continue;
      const int pid = std::atoi(n.c_str() + k + 4);
      if (pid > 0 && kill(pid, 0) == 0) continue;  // still writing
      unlink((dir + "/trials/" + n).c_str());
    }
    closedir(d);
  }
}

bool trialDone(const std::string& dir, int t) { return exists(trialFile(dir, t, ".csv")); }

std::vector<std::string> listTrialFiles(const std::string& dir) {
  std::vector<std::string> out;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* ent = readdir(d)) {
      const std::string n = ent->d_name;
      if (n.rfind("trial_", 0) == 0 && n.find(".tmp") == std::string::npos && n.find(".log") == std::string::npos)
        out.push_back(n);
    }
    closedir(d);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace simswift::experiment
