#include "sim/experiment/Batch.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <dirent.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "agent/libagent/SharedNames.hpp"
#include "sim/bridge/BodyHost.hpp"
#include "sim/experiment/Figures.hpp"
#include "sim/experiment/PrivateShm.hpp"
#include "sim/experiment/Report.hpp"
#include "sim/experiment/Statistics.hpp"
#include "sim/experiment/SweepReport.hpp"
#include "sim/experiment/Trial.hpp"

namespace simswift::experiment {

namespace {

using Clock = std::chrono::steady_clock;

volatile sig_atomic_t g_stop = 0;
void onSignal(int) { g_stop = 1; }

bool exists(const std::string& p) {
  struct stat st;
  return stat(p.c_str(), &st) == 0;
}

void makeDir(const std::string& p) {
  if (mkdir(p.c_str(), 0755) != 0 && errno != EEXIST)
    throw BatchError("cannot create folder " + p + ": " + std::strerror(errno));
}

void makeDirs(const std::string& p) {
  for (size_t i = 1; i <= p.size(); ++i)
    if (i == p.size() || p[i] == '/') makeDir(p.substr(0, i));
}

std::string readFile(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw BatchError("cannot read " + p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Written to a temporary name, flushed, then renamed: a reader sees the whole
// file or none (kill -9 included).
void writeAtomic(const std::string& p, const std::string& text) {
  const std::string tmp = p + ".tmp" + std::to_string(getpid());
  const int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) throw BatchError("cannot write " + tmp + ": " + std::strerror(errno));
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      close(fd);
      throw BatchError("cannot write " + tmp + ": " + std::strerror(errno));
    }
    done += static_cast<size_t>(n);
  }
  fsync(fd);
  close(fd);
  if (rename(tmp.c_str(), p.c_str()) != 0) throw BatchError("cannot rename " + tmp + ": " + std::strerror(errno));
}

std::string fmtDuration(double s) {
  char buf[32];
  if (s < 0 || !std::isfinite(s)) return "?";
  const long t = std::lround(s);
  if (t >= 3600) std::snprintf(buf, sizeof buf, "%ldh%02ldm", t / 3600, (t / 60) % 60);
  else std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  return buf;
}

// The experiment's text in the folder: written once, then it must match.
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

std::string tail(const std::string& path, size_t max_chars) {
  if (!exists(path)) return "";
  std::string s = readFile(path);
  if (s.size() > max_chars) s = "..." + s.substr(s.size() - max_chars);
  while (!s.empty() && s.back() == '\n') s.pop_back();
  return s;
}

struct Progress {
  bool bar = false, lines = true;
  int total = 0, done = 0, failed = 0, ran = 0;
  Clock::time_point start = Clock::now();
  void trial(const Experiment& e, const TrialResult& r, int jobs) {
    ++done;
    ++ran;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    const double eta = elapsed / ran * (total - done);
    char what[200];
    const std::string cell = r.cell >= 0 ? "cell " + std::to_string(r.cell) + ", " : "";
    std::snprintf(what, sizeof what, "trial %d (%s%s, pos %d, #%d): %s | %.1fx real time per core", r.trial, cell.c_str(),
                  r.setup.c_str(), r.position, r.repeat + 1,
                  r.found ? ("found in " + fixed(r.seconds, 2) + " s by " + r.finder).c_str() : "not found",
                  r.realTimeFactor());
    if (bar) {
      const int w = 30, fill = total ? done * w / total : w;
      std::fprintf(stderr, "\r\033[K[%s%s] %d/%d  ETA %s  %s", std::string(fill, '#').c_str(),
                   std::string(w - fill, '.').c_str(), done, total, fmtDuration(eta).c_str(), what);
      std::fflush(stderr);
    } else if (lines) {
      std::fprintf(stderr, "%d/%d %s | ETA %s\n", done, total, what, fmtDuration(eta).c_str());
    }
  }
  void fail(int t, const std::string& why) {
    ++failed;
    if (bar) std::fprintf(stderr, "\r\033[K");
    std::fprintf(stderr, "trial %d failed: %s\n", t, why.c_str());
  }
  void end() {
    if (bar) std::fprintf(stderr, "\n");
  }
};

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

}  // namespace

std::string trialFile(const std::string& dir, int trial, const std::string& suffix) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "trial_%06d", trial);
  return dir + "/trials/" + buf + suffix;
}

void runAndWriteTrial(const Experiment& e, const TrialHooks& hooks, int trial, const std::string& dir) {
  // Launched programs' logs and setups: dir/trials/<trial>/.
  TrialResult r = runTrial(e, trial, hooks, dir + "/trials/" + std::to_string(trial));
  // This process's peak resident memory: the trial's worker (ru_maxrss is in
  // KiB on Linux; launched robot programs are processes of their own).
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) == 0) r.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  writeAtomic(trialFile(dir, trial, ".tracks.csv"), tracksRows(r, e));
  writeAtomic(trialFile(dir, trial, ".timing.csv"), timingRow(r));
  writeAtomic(trialFile(dir, trial, ".csv"), csvRow(r, static_cast<int>(r.robots.size())));  // last: "done"
}

std::string runSingleTrial(const Experiment& e, const TrialHooks& hooks, int trial, const std::string& out_dir) {
  checkBehaviours(e, hooks);
  if (trial < 0 || trial >= e.numTrials())
    throw BatchError("--trial " + std::to_string(trial) + ": the experiment has trials 0.." +
                     std::to_string(e.numTrials() - 1));
  claimFolder(e, out_dir);
  runAndWriteTrial(e, hooks, trial, out_dir);
  return readFile(trialFile(out_dir, trial, ".csv"));
}

BatchOutcome runBatch(const Experiment& e, const TrialHooks& hooks, const BatchOptions& opt) {
  checkBehaviours(e, hooks);  // before any trial: refuses what this build cannot run
  if (opt.shards < 1 || opt.shard < 1 || opt.shard > opt.shards) throw BatchError("bad shard");
  claimFolder(e, opt.out_dir);

  BatchOutcome out;
  std::vector<int> todo;
  for (int t = opt.shard - 1; t < e.numTrials(); t += opt.shards) {
    ++out.trials;
    if (trialDone(opt.out_dir, t)) ++out.already;
    else todo.push_back(t);
  }
  int jobs = opt.jobs > 0 ? opt.jobs : static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
  jobs = std::max(1, std::min<int>(jobs, static_cast<int>(todo.size())));

  Progress pr;
  pr.total = out.trials;
  pr.done = out.already;
  const bool tty = isatty(STDERR_FILENO);
  pr.bar = opt.progress == BatchOptions::Progress::Bar || (opt.progress == BatchOptions::Progress::Auto && tty);
  pr.lines = opt.progress != BatchOptions::Progress::None;
  if (pr.lines && out.already > 0)
    std::fprintf(stderr, "%s: %d of %d trials already done, resuming\n", opt.out_dir.c_str(), out.already,
                 out.trials);

  // Ctrl-C / SIGTERM: stop launching, let running trials end (they get the
  // terminal's SIGINT too), keep every finished one.
  struct sigaction sa {}, old_int{}, old_term{};
  sa.sa_handler = onSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;  // no SA_RESTART: waitpid returns on a signal
  g_stop = 0;
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);

  std::fflush(stdout);
  std::fflush(stderr);
  RunWall wall;
  wall.jobs = jobs;
  // Launched robot programs open their release's fixed names: each worker
  // gets its own /dev/shm (PrivateShm.hpp), or the trials run one at a time.
  bool launches = false;
  for (const Setup& s : e.setups)
    for (const ExperimentRobot& r : s.robots) launches = launches || r.launch.launched();
  bool private_shm = false;
  if (launches) {
    std::string why;
    private_shm = privateShmAvailable(&why);
    if (!private_shm && jobs > 1) {
      std::fprintf(stderr,
                   "simswift: this machine gives no private /dev/shm to a trial (%s); launched robot programs "
                   "share names, so the trials run one at a time\n",
                   why.c_str());
      jobs = 1;
    }
  }
  const Clock::time_point wall0 = Clock::now();
  std::map<pid_t, int> running;
  size_t next = 0;
  while ((next < todo.size() && !g_stop) || !running.empty()) {
    while (!g_stop && next < todo.size() && static_cast<int>(running.size()) < jobs) {
      const int t = todo[next++];
      const pid_t pid = fork();
      if (pid < 0) throw BatchError(std::string("fork: ") + std::strerror(errno));
      if (pid == 0) {
        // The worker: one trial, messages into its log, then _exit (robot
        // threads that did not answer a watchdog cannot be joined).
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        const std::string log = trialFile(opt.out_dir, t, ".log");
        const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
          dup2(fd, STDOUT_FILENO);
          dup2(fd, STDERR_FILENO);
          close(fd);
        }
        int code = 0;
        try {
          if (private_shm) {
            const std::string err = enterPrivateShm();
            if (!err.empty()) throw BatchError("a private /dev/shm for the trial: " + err);
          }
          runAndWriteTrial(e, hooks, t, opt.out_dir);
        } catch (const ConfigError& ex) {
          std::fprintf(stderr, "%s\n", ex.what());
          code = 2;
        } catch (const std::exception& ex) {
          std::fprintf(stderr, "%s\n", ex.what());
          code = 1;
        }
        std::fflush(stdout);
        std::fflush(stderr);
        if (code == 0) unlink(log.c_str());
        bridge::cleanup::removeAll();
        _exit(code);
      }
      running[pid] = t;
    }
    if (running.empty()) break;
    int status = 0;
    rusage usage{};  // the trial process's own: its peak resident memory
    const pid_t pid = wait4(-1, &status, 0, &usage);
    if (pid < 0) {
      if (errno == EINTR) {
        if (g_stop)
          for (const auto& [p, t] : running) kill(p, SIGTERM);  // a signal to us alone: pass it on
        continue;
      }
      throw BatchError(std::string("waitpid: ") + std::strerror(errno));
    }
    auto it = running.find(pid);
    if (it == running.end()) continue;  // not ours
    const int t = it->second;
    running.erase(it);
    wall.peak_trial_mb = std::max(wall.peak_trial_mb, static_cast<double>(usage.ru_maxrss) / 1024.0);  // KiB -> MB
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && trialDone(opt.out_dir, t)) {
      TrialResult r = parseCsvRow(readFile(trialFile(opt.out_dir, t, ".csv")), static_cast<int>(e.sweep.size()));
      parseTimingRow(readFile(trialFile(opt.out_dir, t, ".timing.csv")), r);
      pr.trial(e, r, jobs);
      ++out.ran;
      ++wall.ran;
      wall.trial_sim_s += r.sim_s;
      wall.trial_wall_s += r.wall_s;
    } else if (g_stop) {
      unlink(trialFile(opt.out_dir, t, ".log").c_str());  // interrupted, not failed
    } else {
      const std::string why = WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                                                  : "exit code " + std::to_string(WEXITSTATUS(status));
      pr.fail(t, why + ": " + tail(trialFile(opt.out_dir, t, ".log"), 600) + " (log: " +
                     trialFile(opt.out_dir, t, ".log") + ")");
      ++out.failed;
    }
  }
  pr.end();
  wall.wall_s = std::chrono::duration<double>(Clock::now() - wall0).count();
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  out.interrupted = g_stop != 0;

  const int done = out.already + out.ran;
  std::ostringstream m;
  if (out.interrupted) {
    m << "interrupted: " << done << " of " << out.trials
      << " trials kept in " << opt.out_dir << "; run the same command again to continue";
  } else if (out.failed) {
    m << out.failed << " trial(s) failed (logs in " << opt.out_dir << "/trials); rerun to retry them";
  } else {
    bool all = true;
    for (int t = 0; t < e.numTrials() && all; ++t) all = trialDone(opt.out_dir, t);
    if (all) {
      std::string notes;
      // A rerun in a finished folder changes nothing (the report keeps the
      // wall clock of the run that finished it).
      if (wall.ran > 0 || !exists(opt.out_dir + "/report.md")) assemble(e, opt.out_dir, &notes, &wall);
      out.assembled = true;
      m << notes;
      if (wall.ran > 0)
        m << "ran " << wall.ran << " trial(s) with " << jobs << " worker(s) in " << fmtDuration(wall.wall_s)
          << " of wall time (" << fixed(wall.wall_s > 0 ? wall.trial_sim_s / wall.wall_s : 0, 1)
          << " simulated s per wall s; peak memory of one trial process " << fixed(wall.peak_trial_mb, 0)
          << " MB)\n";
      m << "report: " << opt.out_dir << "/report.md (also results.csv, tracks.csv, figures/, timing.md)";
    } else {
      m << "shard " << opt.shard << "/" << opt.shards << ": " << done << " trials in " << opt.out_dir
        << "; join the shards with `simswift experiment merge DIR... --out DIR`";
    }
  }
  out.message = m.str();
  return out;
}

BatchOutcome mergeRuns(const std::vector<std::string>& dirs, const std::string& out_dir) {
  if (dirs.empty()) throw BatchError("merge: no folders given");
  const std::string text = readFile(dirs[0] + "/experiment.yaml");
  for (const std::string& d : dirs)
    if (readFile(d + "/experiment.yaml") != text)
      throw BatchError(d + "/experiment.yaml differs from " + dirs[0] + "/experiment.yaml: not shards of one experiment");
  const Experiment e = Experiment::parse(text, dirs[0] + "/experiment.yaml");
  claimFolder(e, out_dir);
  for (const std::string& d : dirs) {
    for (const std::string& f : listTrialFiles(d + "/trials")) {
      const std::string src = d + "/trials/" + f, dst = out_dir + "/trials/" + f;
      const std::string body = readFile(src);
      if (exists(dst)) {
        // Results must agree; timing (wall clock) may differ between hosts.
        if (f.find(".timing.") == std::string::npos && readFile(dst) != body)
          throw BatchError(src + " differs from " + dst + ": the folders disagree about a trial");
        continue;
      }
      writeAtomic(dst, body);
    }
  }
  BatchOutcome o;
  o.trials = e.numTrials();
  std::vector<int> missing;
  for (int t = 0; t < e.numTrials(); ++t)
    if (!trialDone(out_dir, t)) missing.push_back(t);
  o.already = o.trials - static_cast<int>(missing.size());
  if (missing.empty()) {
    std::string notes;
    assemble(e, out_dir, &notes);
    o.assembled = true;
    o.message = notes + "merged " + std::to_string(dirs.size()) + " folder(s) into " + out_dir + ": " +
                std::to_string(o.trials) + " trials";
  } else {
    std::ostringstream m;
    m << "merged into " << out_dir << ", but " << missing.size() << " of " << o.trials
      << " trials are missing (first: " << missing[0] << "); run the missing shards, then merge again";
    o.message = m.str();
    o.failed = static_cast<int>(missing.size());
  }
  return o;
}

void assemble(const Experiment& e, const std::string& dir, std::string* notes, const RunWall* run) {
  const int robots = e.maxRobots();
  std::vector<TrialResult> results;
  std::string csv = csvHeader(robots, e.sweep), tracks = tracksHeader(), timing = timingHeader();
  for (int t = 0; t < e.numTrials(); ++t) {
    if (!trialDone(dir, t)) throw BatchError("trial " + std::to_string(t) + " missing in " + dir);
    TrialResult r;
    try {
      r = parseCsvRow(readFile(trialFile(dir, t, ".csv")), static_cast<int>(e.sweep.size()));
    } catch (const std::runtime_error& ex) {
      throw BatchError(trialFile(dir, t, ".csv") + ": " + ex.what());
    }
    if (r.trial != t) throw BatchError(trialFile(dir, t, ".csv") + ": holds trial " + std::to_string(r.trial));
    csv += csvRow(r, robots);
    tracks += readFile(trialFile(dir, t, ".tracks.csv"));
    const std::string tm = trialFile(dir, t, ".timing.csv");
    if (exists(tm)) {
      const std::string row = readFile(tm);
      timing += row;
      parseTimingRow(row, r);
    }
    results.push_back(r);
  }
  writeAtomic(dir + "/results.csv", csv);
  writeAtomic(dir + "/tracks.csv", tracks);
  writeAtomic(dir + "/timing.csv", timing);
  writeAtomic(dir + "/report.md", reportMarkdown(e, results) + "\n" + wallClockSection(e, results, run));

  // timing.md: real-time factor per trial (simulated s / wall s, per core).
  {
    std::ostringstream s;
    double sim = 0, wall = 0;
    std::vector<double> rtf, peak;
    for (const TrialResult& r : results) {
      sim += r.sim_s;
      wall += r.wall_s;
      if (r.wall_s > 0) rtf.push_back(r.realTimeFactor());
      if (r.peak_mb > 0) peak.push_back(r.peak_mb);
    }
    std::sort(rtf.begin(), rtf.end());
    std::sort(peak.begin(), peak.end());
    s << "# Wall clock of `" << e.name << "`\n\n"
      << "Real-time factor = simulated s / wall s of one trial in one worker process (per core). "
      << "These figures depend on the machine and its load; nothing else in the folder does (but report.md's "
      << "last section, which summarises them).\n\n";
    if (run && run->ran > 0)
      s << "The run that completed this folder: " << run->ran << " trial(s), " << run->jobs << " worker process(es), "
        << fixed(run->wall_s, 1) << " s of wall time.\n\n";
    if (!rtf.empty())
      s << "Trials " << results.size() << "; simulated " << fixed(sim, 1) << " s in " << fixed(wall, 1)
        << " s of worker time; real-time factor min " << fixed(rtf.front(), 2) << ", median "
        << fixed(stats::median(rtf), 2) << ", max " << fixed(rtf.back(), 2) << ".\n\n";
    if (!peak.empty())
      s << "Peak resident memory of one trial process (MB): min " << fixed(peak.front(), 0) << ", median "
        << fixed(stats::median(peak), 0) << ", max " << fixed(peak.back(), 0) << ".\n\n";
    s << "| Trial | Setup | Position | Simulated s | Wall s | Real-time factor | Peak MB |\n"
         "|---:|---|---:|---:|---:|---:|---:|\n";
    for (const TrialResult& r : results)
      s << "| " << r.trial << " | " << r.setup << " | " << r.position << " | " << fixed(r.sim_s, 2) << " | "
        << fixed(r.wall_s, 2) << " | " << fixed(r.realTimeFactor(), 2) << " | "
        << (r.peak_mb > 0 ? fixed(r.peak_mb, 0) : std::string()) << " |\n";
    writeAtomic(dir + "/timing.md", s.str());
  }

  // Figures.
  makeDir(dir + "/figures");
  std::map<std::string, int> setup_index;
  for (size_t s = 0; s < e.setups.size(); ++s) setup_index[e.setups[s].name] = static_cast<int>(s);
  std::vector<std::vector<RouteSamples>> routes(e.setups.size());
  for (size_t s = 0; s < e.setups.size(); ++s)
    for (const ExperimentRobot& r : e.setups[s].robots)
      routes[s].push_back({agent::libagent::robotTag(r.team, r.player), {}});
  {
    std::istringstream in(tracks);
    std::string line;
    std::getline(in, line);  // header
    char setup[128], player[32];
    double t, x, y, th;
    int trial;
    while (std::getline(in, line)) {
      if (std::sscanf(line.c_str(), "%d,%127[^,],%31[^,],%lf,%lf,%lf,%lf", &trial, setup, player, &t, &x, &y, &th) != 7)
        continue;
      auto it = setup_index.find(setup);
      if (it == setup_index.end()) continue;
      for (RouteSamples& rs : routes[it->second])
        if (rs.player == player) rs.xy.push_back({x, y});
    }
  }
  for (size_t s = 0; s < e.setups.size(); ++s) {
    drawRoutes(e, static_cast<int>(s), routes[s], dir + "/figures/routes_" + e.setups[s].name + ".png");
    std::string msg;
    if (!plotFindTimes(e, static_cast<int>(s), results, dir + "/figures", &msg) && notes) *notes += msg + "\n";
  }
  if (e.swept()) {
    // One row per cell and setup (cells.csv), one figure per swept path.
    const std::vector<CellRow> rows = cellRows(e, results);
    writeAtomic(dir + "/cells.csv", cellsCsv(e, rows));
    for (size_t k = 0; k < e.sweep.size(); ++k) {
      std::string msg;
      if (!plotSweep(e, rows, static_cast<int>(k), dir + "/figures", &msg) && notes) *notes += msg + "\n";
    }
  }
}

}  // namespace simswift::experiment
