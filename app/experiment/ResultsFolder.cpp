#include "app/experiment/ResultsFolder.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "app/experiment/Batch.hpp"
#include "app/experiment/Files.hpp"

namespace simswift::experiment {

std::string trialFile(const std::string& dir, int trial, const std::string& suffix) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "trial_%06d", trial);
  return dir + "/trials/" + buf + suffix;
}

namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  size_t pos = 0;
  while (pos < text.size()) {
    const size_t end = std::min(text.find('\n', pos), text.size());
    out.push_back(text.substr(pos, end - pos));
    pos = end + 1;
  }
  return out;
}

// Where two different texts first differ: "line N: 'a' in A, 'b' in B".
std::string firstDifference(const std::string& a, const std::string& b, const std::string& a_name,
                            const std::string& b_name) {
  const std::vector<std::string> la = lines(a), lb = lines(b);
  size_t i = 0;
  while (i < la.size() && i < lb.size() && la[i] == lb[i]) ++i;
  auto shown = [i](const std::vector<std::string>& l) {
    if (i >= l.size()) return std::string("the end of the file");
    return "'" + (l[i].size() <= 80 ? l[i] : l[i].substr(0, 80) + "...") + "'";
  };
  return "line " + std::to_string(i + 1) + ": " + shown(la) + " in " + a_name + ", " + shown(lb) + " in " + b_name;
}

}  // namespace

FolderLock::FolderLock(const std::string& dir) {
  const std::string path = dir + "/.lock";
  try {
    common::lock::PidLock lock(path);
    if (lock.tryLock(kWorkerEndWait_s)) {
      lock_ = std::move(lock);
      return;
    }
    const int pid = lock.holderPid();
    if (pid > 0 && (kill(pid, 0) == 0 || errno == EPERM))
      throw BatchError(dir + " is in use by another simswift run (pid " + std::to_string(pid) +
                       "): a second run into it would repeat its trials; wait for it to end or stop it, or "
                       "choose another --out");
    throw BatchError(dir + " is still locked by the workers of a run that has ended (pid " +
                     (pid > 0 ? std::to_string(pid) : std::string("unknown")) + "): `fuser " + path +
                     "` names them; stop them, then run again");
  } catch (const common::lock::LockError& e) {
    throw BatchError(e.what());
  }
}

FolderLock claimFolder(const Experiment& e, const std::string& dir) {
  return claimFolder(e.text, e.source, dir, "experiment.yaml");
}

FolderLock claimFolder(const std::string& text, const std::string& source, const std::string& dir,
                       const std::string& copy_name) {
  makeDirs(dir + "/trials");
  FolderLock lock(dir);
  const std::string copy = dir + "/" + copy_name;
  const std::string kind = copy_name == "experiment.yaml" ? "experiment" : "test";
  if (exists(copy)) {
    const std::string held = readFile(copy);
    if (held != text)
      throw BatchInputError(dir + " holds results of a different " + kind + " file: " + copy + " differs from " +
                            source + " (first at " + firstDifference(held, text, copy, source) +
                            "); choose another --out or remove the folder");
  } else {
    writeAtomic(copy, text);
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
  return lock;
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
