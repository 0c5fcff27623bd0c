// Batch runs of a tiny script-robot experiment (4-6 trials of 7 s): results
// are a pure function of the file -- across reruns, --jobs, shards + merge
// and a kill -9 followed by a resume -- and the report's numbers follow
// from results.csv. Also the found rule and the fallen-robot rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <map>
#include <sstream>
#include <string>
#include <cerrno>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include "sim/programs/Programs.hpp"
#include "app/experiment/Batch.hpp"
#include "app/experiment/Report.hpp"
#include "app/experiment/ResultsFolder.hpp"
#include "app/experiment/Trial.hpp"
#include "tests/experiment/ExperimentTestUtil.hpp"

using namespace simswift;
using namespace simswift::experiment;
using exptest::readAll;
using exptest::runInto;

namespace {

// Everything but the wall clock (timing.*, report.md's last section) is
// byte-identical.
void expectSameResults(const std::string& a, const std::string& b) {
  for (const char* f : {"results.csv", "tracks.csv", "report.md", "figures/routes_walker.png",
                        "figures/findtime_walker.dat"}) {
    std::string x = readAll(a + "/" + f), y = readAll(b + "/" + f);
    if (std::string(f) == "report.md") {
      EXPECT_NE(x.find(kWallClockHeading), std::string::npos) << a << "/report.md has no wall-clock section";
      x = deterministicPart(x);
      y = deterministicPart(y);
      EXPECT_EQ(x.find(kWallClockHeading), std::string::npos);
    }
    EXPECT_FALSE(x.empty()) << a << "/" << f;
    EXPECT_TRUE(x == y) << f << " differs between " << a << " and " << b;
  }
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) out.push_back(cur);
  if (!s.empty() && s.back() == sep) out.push_back("");
  return out;
}

// tinyExperiment without its found ball: the robot never finds position 2,
// so every trial runs its whole time limit (3600 s simulated: tens of
// seconds of wall clock, far longer than the tests below wait).
std::string neverFound(int trials) {
  std::string s = exptest::tinyExperiment(trials, 3600.0);
  const std::string found = "  - {position: 1, x: 0.7, y: 0.0}\n";
  s.erase(s.find(found), found.size());
  return s;
}

// `simswift experiment FILE --out OUT ARGS... --progress none` in its own
// process group (for the cleanup only), stderr into `err`.
pid_t startBatch(const std::string& file, const std::string& out, std::vector<std::string> args,
                 const std::string& err) {
  const std::string bin = exptest::simswiftBinary();
  std::vector<std::string> all = {bin, "experiment", file, "--out", out, "--progress", "none"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    if (!freopen(err.c_str(), "w", stderr)) _exit(126);
    execv(bin.c_str(), argv.data());
    _exit(127);
  }
  setpgid(pid, pid);
  return pid;
}

// Waits up to `seconds` for `n` live children of `pid` (its workers).
std::vector<pid_t> waitForWorkers(pid_t pid, size_t n, double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  std::vector<pid_t> w = exptest::childrenOf(pid);
  while (w.size() < n && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    w = exptest::childrenOf(pid);
  }
  return w;
}

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

}  // namespace

TEST(Batch, RerunsAndJobCountsGiveIdenticalResults) {
  const Experiment e = Experiment::parse(exptest::tinyExperiment(2), "tiny.yaml");
  const std::string a = exptest::freshDir("a"), b = exptest::freshDir("b"), c = exptest::freshDir("c");
  const BatchOutcome oa = runInto(e, a, 1);
  EXPECT_TRUE(oa.assembled) << oa.message;
  EXPECT_EQ(oa.ran, 4);
  // The report's wall-clock part: each setup's real-time factors (per core)
  // and the run's wall time.
  {
    const std::string rep = readAll(a + "/report.md");
    const std::string wall = rep.substr(rep.find(kWallClockHeading));
    std::vector<std::string> cells;
    for (const std::string& l : split(wall, '\n'))
      if (l.rfind("| `walker` |", 0) == 0) cells = split(l, '|');
    ASSERT_EQ(cells.size(), 9u) << wall;  // 7 cells between 8 bars
    EXPECT_EQ(std::stoi(cells[2]), 4);    // trials
    // Simulated s: 1 s penalised + 7 s (not found) or + 3..7 s (found).
    EXPECT_GE(std::stod(cells[3]), 4 * (1.0 + 3.0));
    EXPECT_LE(std::stod(cells[3]), 4 * (1.0 + 7.0) + 0.1);
    EXPECT_GT(std::stod(cells[6]), 0.0);                    // median real-time factor
    EXPECT_LE(std::stod(cells[5]), std::stod(cells[6]));
    EXPECT_LE(std::stod(cells[6]), std::stod(cells[7]));
    EXPECT_NE(wall.find("ran 4 trial(s) with 1 worker process(es)"), std::string::npos) << wall;
  }
  EXPECT_TRUE(runInto(e, b, 2).assembled);
  EXPECT_TRUE(runInto(e, c, 2).assembled);
  expectSameResults(a, b);
  expectSameResults(b, c);
  // A second run in a finished folder runs nothing and changes nothing.
  const std::string before = readAll(a + "/results.csv");
  const BatchOutcome again = runInto(e, a, 2);
  EXPECT_EQ(again.already, 4);
  EXPECT_EQ(again.ran, 0);
  EXPECT_EQ(readAll(a + "/results.csv"), before);

  // What the trials did: position 1 lies 1.2 m ahead of the walker (found
  // once the torso is within 0.3 m: ~0.9 m at ~0.2 m/s, so 3-7 s); position
  // 2 lies 1.5 m to its left and is never found.
  const std::vector<std::string> lines = split(readAll(a + "/results.csv"), '\n');
  ASSERT_GE(lines.size(), 5u);
  for (int i = 1; i <= 4; ++i) {
    const TrialResult r = parseCsvRow(lines[i]);
    if (r.position == 1) {
      EXPECT_TRUE(r.found) << lines[i];
      EXPECT_GT(r.seconds, 3.0);
      EXPECT_LT(r.seconds, 7.0);
      EXPECT_EQ(r.finder, "t19p2");
      EXPECT_NEAR(r.robots[0].distance_m, 0.9, 0.25) << lines[i];
    } else {
      EXPECT_FALSE(r.found) << lines[i];
    }
    EXPECT_EQ(r.robots[0].falls, 0);
  }
  // One trial in this process (--trial) gives the worker's row.
  EXPECT_EQ(runSingleTrial(e, behaviourHooks(), 2, exptest::freshDir("single")), readAll(trialFile(a, 2, ".csv")));
  // Noise on, different seeds: the two position-1 trials differ a little.
  EXPECT_NE(parseCsvRow(lines[1]).seed, parseCsvRow(lines[2]).seed);
}

TEST(Batch, TwoShardsMergedEqualOneRun) {
  const Experiment e = Experiment::parse(exptest::tinyExperiment(2), "tiny.yaml");
  const std::string one = exptest::freshDir("one"), s1 = exptest::freshDir("s1"), s2 = exptest::freshDir("s2"),
                    merged = exptest::freshDir("merged");
  ASSERT_TRUE(runInto(e, one, 2).assembled);
  const BatchOutcome o1 = runInto(e, s1, 1, 1, 2);
  EXPECT_EQ(o1.trials, 2);
  EXPECT_FALSE(o1.assembled);  // half the trials
  runInto(e, s2, 1, 2, 2);
  EXPECT_FALSE(exptest::fileExists(s1 + "/results.csv"));
  const BatchOutcome part = mergeRuns({s1}, merged);
  EXPECT_FALSE(part.assembled);  // one shard is not enough
  const BatchOutcome m = mergeRuns({s1, s2}, merged);
  EXPECT_TRUE(m.assembled) << m.message;
  expectSameResults(one, merged);
  // Shards of another experiment are refused.
  const Experiment other = Experiment::parse(exptest::tinyExperiment(1), "tiny.yaml");
  const std::string o = exptest::freshDir("other");
  runInto(other, o, 1, 1, 2);
  EXPECT_THROW(mergeRuns({s1, o}, exptest::freshDir("bad")), BatchError);
  // So is reusing a folder for another experiment.
  EXPECT_THROW(runInto(other, s1, 1), BatchError);
}

// kill -9 of the whole run (parent and worker) after the first trial: the
// rerun keeps the finished trials and ends byte-identical to a clean run.
TEST(Batch, KillMinus9ThenResumeEqualsUninterruptedRun) {
  const std::string dir = exptest::freshDir("kill"), clean = exptest::freshDir("clean");
  const std::string file = dir + "/tiny.yaml";
  exptest::writeAll(file, exptest::tinyExperiment(3));  // 6 trials
  const std::string out = dir + "/out";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    setpgid(0, 0);  // its own group, so the worker can be killed with it
    const std::string bin = exptest::simswiftBinary();
    freopen("/dev/null", "w", stderr);
    execl(bin.c_str(), bin.c_str(), "experiment", file.c_str(), "--out", out.c_str(), "--jobs", "1", "--progress",
          "lines", static_cast<char*>(nullptr));
    _exit(127);
  }
  setpgid(pid, pid);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!exptest::fileExists(trialFile(out, 0, ".csv")) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(-pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(exptest::fileExists(trialFile(out, 0, ".csv"))) << "no trial finished within 120 s";
  ASSERT_FALSE(exptest::fileExists(out + "/results.csv")) << "the run ended before the kill: test proves nothing";
  EXPECT_FALSE(exptest::fileExists(trialFile(out, 5, ".csv")));

  const std::string resume = exptest::simswiftBinary() + " experiment '" + file + "' --out '" + out +
                             "' --jobs 2 --progress lines 2> '" + dir + "/resume.txt'";
  const int rc = std::system(resume.c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 0) << readAll(dir + "/resume.txt");
  EXPECT_NE(readAll(dir + "/resume.txt").find("already done, resuming"), std::string::npos) << readAll(dir + "/resume.txt");
  EXPECT_NE(readAll(dir + "/resume.txt").find("x real time"), std::string::npos);  // per-trial RTF

  const Experiment e = Experiment::loadFile(file);
  ASSERT_TRUE(runInto(e, clean, 2).assembled);
  expectSameResults(clean, out);
}

// kill -9 of the batch's own process alone (not its group, as `kill -9
// <pid>` does): its workers die with it (PR_SET_PDEATHSIG), and the folder
// is free at once for a resume. Before issue 34 they ran on under pid 1,
// and a resume ran their trials a second time beside them.
TEST(Batch, KillMinus9OfTheBatchAloneEndsItsWorkers) {
  const std::string dir = exptest::freshDir("orphans");
  const std::string file = dir + "/long.yaml", out = dir + "/out";
  exptest::writeAll(file, neverFound(2));
  const pid_t pid = startBatch(file, out, {"--jobs", "2"}, dir + "/err.txt");
  ASSERT_GT(pid, 0);
  const std::vector<pid_t> workers = waitForWorkers(pid, 2, 60);
  ASSERT_EQ(workers.size(), 2u) << "the batch did not start two workers within 60 s: " << readAll(dir + "/err.txt");
  kill(pid, SIGKILL);  // the batch alone
  waitpid(pid, nullptr, 0);
  // The kernel kills them as their parent exits: milliseconds; 5 s is slack
  // for a loaded machine (a trial runs far longer).
  const std::vector<pid_t> left = exptest::stillAliveAfter(workers, 5.0);
  EXPECT_TRUE(left.empty()) << left.size() << " worker(s) outlived their killed batch, e.g. pid " << left[0];
  kill(-pid, SIGKILL);  // whatever is left of the group: the test's own cleanup
  EXPECT_FALSE(exptest::fileExists(out + "/results.csv"));
  if (left.empty()) {
    EXPECT_NO_THROW(FolderLock{out}) << "the folder is still locked after its run and workers died";
  }
}

// Two runs of the same shard into one folder at once: the second is refused
// before it runs anything, naming the folder and the first run's pid (exit
// code 1, as an I/O failure: the same command succeeds once the first run
// has ended). Before issue 34 both ran every trial and both exited 0.
TEST(Batch, ASecondRunIntoAFolderInUseIsRefusedNamingTheHolder) {
  const std::string dir = exptest::freshDir("busy");
  const std::string file = dir + "/long.yaml", out = dir + "/out";
  exptest::writeAll(file, neverFound(2));
  const pid_t first = startBatch(file, out, {"--jobs", "1", "--shard", "1/2"}, dir + "/first.txt");
  ASSERT_GT(first, 0);
  ASSERT_EQ(waitForWorkers(first, 1, 60).size(), 1u) << "no worker within 60 s: " << readAll(dir + "/first.txt");
  const pid_t second = startBatch(file, out, {"--jobs", "1", "--shard", "1/2"}, dir + "/second.txt");
  ASSERT_GT(second, 0);
  int status = 0;
  pid_t ended = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while ((ended = waitpid(second, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  if (ended == 0) {
    kill(-second, SIGKILL);
    waitpid(second, nullptr, 0);
  }
  EXPECT_TRUE(exptest::processAlive(first)) << "the first run ended: " << readAll(dir + "/first.txt");
  kill(-first, SIGKILL);
  waitpid(first, nullptr, 0);
  ASSERT_EQ(ended, second) << "the second run was still running after 30 s (it ran the first run's trials)";
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  const std::string err = readAll(dir + "/second.txt");
  EXPECT_NE(err.find(out + " is in use by another simswift run (pid " + std::to_string(first) + ")"), std::string::npos)
      << err;
  EXPECT_FALSE(exptest::fileExists(trialFile(out, 0, ".csv")));
}

// The lock in one process: a second claim on a held folder is refused with
// this process's pid; released, the folder can be claimed again.
TEST(Batch, AFolderLockIsExclusiveUntilReleased) {
  const std::string dir = exptest::freshDir("lock");
  const Experiment e = Experiment::parse(exptest::tinyExperiment(1), "tiny.yaml");
  {
    const FolderLock held = claimFolder(e, dir);
    try {
      const FolderLock again = claimFolder(e, dir);
      ADD_FAILURE() << "claimed twice";
    } catch (const BatchError& err) {
      EXPECT_EQ(std::string(err.what()).rfind(dir + " is in use by another simswift run (pid " +
                                                  std::to_string(getpid()) + ")", 0),
                0u)
          << err.what();
    }
  }
  EXPECT_NO_THROW(FolderLock{dir});
}

// A run killed with kill -9 leaves its folder locked only while its workers
// are still dying (they inherited the lock): the next run waits for them
// instead of refusing. Here the "worker" holds the lock until the test
// releases it (no timing decides the outcome: the lock is checked held after
// its run died, then released while the next run waits, up to kWorkerEndWait_s).
TEST(Batch, ALockHeldByADeadRunsLastWorkerIsWaitedFor) {
  const std::string dir = exptest::freshDir("dying");
  int started[2], release[2];
  ASSERT_EQ(pipe(started), 0);
  ASSERT_EQ(pipe(release), 0);
  const pid_t run = fork();
  ASSERT_GE(run, 0);
  if (run == 0) {
    const FolderLock held(dir);
    if (fork() == 0) {  // the worker: holds the inherited lock until released
      close(release[1]);
      const char c = 'w';
      if (write(started[1], &c, 1) != 1) _exit(1);
      char r;
      while (read(release[0], &r, 1) > 0) {
      }
      _exit(0);
    }
    _exit(0);  // the run dies first
  }
  close(started[1]);
  close(release[0]);
  char c = 0;
  ASSERT_EQ(read(started[0], &c, 1), 1);
  close(started[0]);
  waitpid(run, nullptr, 0);
  {  // the run is dead, its worker still holds the lock
    const int fd = open((dir + "/.lock").c_str(), O_RDWR | O_CLOEXEC);
    ASSERT_GE(fd, 0);
    EXPECT_EQ(flock(fd, LOCK_EX | LOCK_NB), -1) << "the lock was free: the worker did not hold it";
    EXPECT_EQ(errno, EWOULDBLOCK);
    close(fd);
  }
  std::thread ender([&] {  // the worker ends while the next run waits
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    close(release[1]);
  });
  EXPECT_NO_THROW(FolderLock{dir});
  ender.join();
}

// Rerunning into a folder of another experiment file is bad input (exit 2,
// as a bad file), and the message names the folder and the first
// difference. It was exit 1 before issue 34.
TEST(Batch, AFolderOfAnotherExperimentIsRefusedAsBadInput) {
  const std::string dir = exptest::freshDir("other");
  const std::string out = dir + "/out", file = dir + "/tiny.yaml";
  { const FolderLock claimed = claimFolder(Experiment::parse(exptest::tinyExperiment(2), "first.yaml"), out); }
  exptest::writeAll(file, exptest::tinyExperiment(1));
  const std::string cmd = exptest::simswiftBinary() + " experiment '" + file + "' --out '" + out +
                          "' --progress none 2> '" + dir + "/err.txt'";
  const int rc = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 2);
  const std::string err = readAll(dir + "/err.txt");
  EXPECT_NE(err.find(out + " holds results of a different experiment file: " + out + "/experiment.yaml differs from " +
                     file + " (first at line 4: 'trials_per_position: 2' in " + out +
                     "/experiment.yaml, 'trials_per_position: 1' in " + file + ")"),
            std::string::npos)
      << err;
  EXPECT_FALSE(exptest::fileExists(trialFile(out, 0, ".csv")));
}

// report.md's table rows recomputed here from results.csv: tests, found,
// not found, total, average (Total / Found), population SD; and the Average
// row as the mean of the position rows.
TEST(Batch, ReportNumbersFollowFromTheCsv) {
  const Experiment e = Experiment::parse(exptest::tinyExperiment(3), "tiny.yaml");
  const std::string dir = exptest::freshDir("report");
  ASSERT_TRUE(runInto(e, dir, 2).assembled);
  std::map<int, std::vector<double>> times;
  std::map<int, int> tests;
  const std::vector<std::string> lines = split(readAll(dir + "/results.csv"), '\n');
  ASSERT_EQ(split(lines[0], ',')[5], "found");
  ASSERT_EQ(split(lines[0], ',')[6], "seconds");
  for (size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    const std::vector<std::string> f = split(lines[i], ',');
    const int pos = std::stoi(f[2]);
    ++tests[pos];
    if (f[5] == "1") times[pos].push_back(std::stod(f[6]));
  }
  ASSERT_EQ(tests.size(), 2u);
  std::map<std::string, std::vector<std::string>> rows;  // first cell -> cells
  for (const std::string& l : split(readAll(dir + "/report.md"), '\n')) {
    if (l.rfind("| ", 0) != 0) continue;
    std::vector<std::string> cells = split(l, '|');
    std::vector<std::string> clean;
    for (size_t k = 1; k + 1 < cells.size(); ++k) clean.push_back(trim(cells[k]));
    if (!clean.empty() && !rows.count(clean[0])) rows[clean[0]] = clean;
  }
  double sum_total = 0, sum_avg = 0, sum_sd = 0;
  for (const auto& [pos, n] : tests) {
    const std::vector<double>& t = times[pos];
    double total = 0;
    for (double x : t) total += x;
    const double avg = t.empty() ? 0 : total / t.size();
    double ss = 0;
    for (double x : t) ss += (x - avg) * (x - avg);
    const double sd = t.size() >= 2 ? std::sqrt(ss / t.size()) : 0;
    sum_total += total;
    sum_avg += avg;
    sum_sd += sd;
    ASSERT_TRUE(rows.count(std::to_string(pos))) << "no row for position " << pos;
    const std::vector<std::string>& r = rows[std::to_string(pos)];
    ASSERT_EQ(r.size(), 7u);
    EXPECT_EQ(std::stoi(r[1]), n);
    EXPECT_EQ(std::stoi(r[2]), static_cast<int>(t.size()));
    EXPECT_EQ(std::stoi(r[3]), n - static_cast<int>(t.size()));
    EXPECT_NEAR(std::stod(r[4]), total, 0.006);
    EXPECT_NEAR(std::stod(r[5]), avg, 0.006);
    EXPECT_NEAR(std::stod(r[6]), sd, 0.006);
  }
  EXPECT_GT(times[1].size(), 0u);  // the test needs finds to mean anything
  const std::vector<std::string>& avg = rows["Average:"];
  ASSERT_EQ(avg.size(), 7u);
  EXPECT_NEAR(std::stod(avg[4]), sum_total / 2, 0.006);
  EXPECT_NEAR(std::stod(avg[5]), sum_avg / 2, 0.006);
  EXPECT_NEAR(std::stod(avg[6]), sum_sd / 2, 0.006);
  const std::vector<std::string>& tot = rows["Total:"];
  EXPECT_EQ(std::stoi(tot[1]), 6);
  EXPECT_EQ(std::stoi(tot[2]), static_cast<int>(times[1].size() + times[2].size()));

  // Each trial process's peak resident memory (MB) is in timing.csv; the
  // report's wall-clock section gives the largest.
  const std::vector<std::string> timing = split(readAll(dir + "/timing.csv"), '\n');
  ASSERT_EQ(timing[0], "trial,sim_s,wall_s,real_time_factor,peak_mb");
  double peak = 0;
  int rows_with_peak = 0;
  for (size_t i = 1; i < timing.size(); ++i) {
    if (timing[i].empty()) continue;
    const std::vector<std::string> f = split(timing[i], ',');
    ASSERT_EQ(f.size(), 5u) << timing[i];
    EXPECT_GT(std::stod(f[4]), 1.0) << timing[i];  // a process holds at least 1 MB
    peak = std::max(peak, std::stod(f[4]));
    ++rows_with_peak;
  }
  EXPECT_EQ(rows_with_peak, 6);
  EXPECT_NE(readAll(dir + "/report.md").find("Peak resident memory of one trial process: " + fixed(peak, 0) +
                                             " MB (the largest of 6 trials"),
            std::string::npos);
  EXPECT_NE(readAll(dir + "/timing.md").find("| Peak MB |"), std::string::npos);
}

// A timing.csv row written before peak_mb: read, memory not recorded.
TEST(Batch, TimingRowsWithAndWithoutPeakMemory) {
  TrialResult r;
  r.trial = 4;
  r.sim_s = 12.5;
  r.wall_s = 0.5;
  r.peak_mb = 42.25;
  TrialResult back;
  parseTimingRow(timingRow(r), back);
  EXPECT_DOUBLE_EQ(back.sim_s, 12.5);
  EXPECT_DOUBLE_EQ(back.wall_s, 0.5);
  EXPECT_NEAR(back.peak_mb, 42.25, 0.05);  // one decimal
  parseTimingRow("4,12.50,0.500,25.00\n", back);
  EXPECT_DOUBLE_EQ(back.sim_s, 12.5);
  EXPECT_EQ(back.peak_mb, 0.0);
}

// The found rule needs the ball in a camera's view: 0.25 m behind a standing
// robot it is near enough but unseen; with `sees: false` it is found at once.
// 0.28 m ahead it is in the bottom camera's view (39.7 deg down + 23.8 deg
// half FOV = 63.5 deg below the horizon; the ball centre is ~61 deg down,
// seen from ~0.41 m above and ~0.23 m behind it); at 0.25 m it is not.
TEST(Batch, FoundRuleNeedsTheBallInView) {
  auto file = [](double ball_x, bool sees) {
    std::ostringstream s;
    s << "name: view\nseed: 3\ntime_limit: 1.0\ntrials_per_position: 1\n"
      << "found: {distance: 0.3, sees: " << (sees ? "true" : "false") << "}\n"
      << "balls: [{position: 1, x: " << ball_x << ", y: 0.0}]\n"
      << "setups:\n  - name: s\n    robots:\n"
      << "      - {team: 19, player: 2, x: 0.0, y: 0.0, theta: 0.0, behaviour: script,"
      << " actions: [{t: 0, action: stand}]}\n";
    return Experiment::parse(s.str(), "view.yaml");
  };
  const TrialResult behind = runTrial(file(-0.25, true), 0, behaviourHooks());
  EXPECT_FALSE(behind.found);
  const TrialResult blind = runTrial(file(-0.25, false), 0, behaviourHooks());
  EXPECT_TRUE(blind.found);
  EXPECT_NEAR(blind.seconds, 0.01, 1e-9);  // the first tick
  const TrialResult ahead = runTrial(file(0.28, true), 0, behaviourHooks());
  EXPECT_TRUE(ahead.found);
  EXPECT_LT(ahead.seconds, 0.05);
}

// "Sees the ball" is what the robot's vision was given (the oracle's
// detector model), not geometry: a ball 0.8 m ahead (found distance 1 m) is
// found on the first frame of play; beyond the detector's range, or hidden
// behind a second robot (facing away, so it does not see the ball itself),
// it is not -- although it is in the camera's view both times.
TEST(Batch, FoundRuleUsesTheRobotsVision) {
  auto file = [](const std::string& vision, bool occluder) {
    std::ostringstream s;
    s << "name: sees\nseed: 4\ntime_limit: 0.5\ntrials_per_position: 1\n"
      << "found: {distance: 1.0, sees: true}\n" << vision
      << "balls: [{position: 1, x: 0.8, y: 0.0}]\n"
      << "setups:\n  - name: s\n    robots:\n"
      << "      - {team: 19, player: 2, x: 0.0, y: 0.0, theta: 0.0, behaviour: script,"
      << " actions: [{t: 0, action: stand}]}\n";
    if (occluder)
      s << "      - {team: 19, player: 3, x: 0.4, y: 0.0, theta: 3.14159, behaviour: script,"
        << " actions: [{t: 0, action: stand}]}\n";
    return Experiment::parse(s.str(), "sees.yaml");
  };
  const TrialResult seen = runTrial(file("", false), 0, behaviourHooks());
  EXPECT_TRUE(seen.found);
  EXPECT_EQ(seen.finder, "t19p2");
  EXPECT_LT(seen.seconds, 0.05);  // the frame at the start of play
  const TrialResult far = runTrial(file("vision: {ball: {max_distance_mm: 600}}\n", false), 0, behaviourHooks());
  EXPECT_FALSE(far.found);
  const TrialResult hidden = runTrial(file("", true), 0, behaviourHooks());
  EXPECT_FALSE(hidden.found);
}

// The trial starts as findballexp's did: penalised (INITIAL) at the start
// poses -- not at the GameController's sideline spot -- for start.penalised
// s, then PLAYING and unpenalised; times count from then. A script robot
// told to walk from t = 0 stands still while penalised.
TEST(Batch, TrialsStartPenalisedThenPlay) {
  struct Watch : FoundRule {
    mutable std::vector<agent::blackboard::GameInfo> seen;  // per call (tick of play)
    mutable std::vector<double> x;                          // robot 0's torso x (m)
    int finder(const Experiment&, runner::Runner& r) const override {
      seen.push_back(r.programs().program(0)->board().game.read());
      x.push_back(r.stats().robots[0].x);
      return -1;
    }
  };
  const std::string text =
      "name: start\nseed: 6\ntime_limit: 2.0\ntrials_per_position: 1\nstart: {penalised: 0.6}\n"
      "tracks: {every: 0.1}\nballs: [{position: 1, x: 3.0, y: -2.0}]\n"
      "setups:\n  - name: s\n    robots:\n"
      "      - {team: 19, player: 3, x: -2.0, y: -2.9, theta: 1.5708, behaviour: script,\n"
      "         actions: [{t: 0, action: walk, forward: 250}]}\n";
  const Experiment e = Experiment::parse(text, "start.yaml");
  TrialHooks hooks = behaviourHooks();
  auto watch = std::make_shared<Watch>();
  hooks.found = watch;
  const TrialResult r = runTrial(e, 0, hooks);
  EXPECT_FALSE(r.found);
  ASSERT_EQ(watch->seen.size(), 200u);  // 2 s of play, every tick
  // The first call: the robot's last frame was taken while it was penalised.
  EXPECT_TRUE(watch->seen.front().known);
  EXPECT_TRUE(watch->seen.front().penalised);
  EXPECT_EQ(watch->seen.front().state, agent::blackboard::GameStateId::INITIAL);
  EXPECT_FALSE(watch->seen.back().penalised);
  EXPECT_EQ(watch->seen.back().state, agent::blackboard::GameStateId::PLAYING);
  // Tracks start at PLAYING (t = 0) on the start pose (1 cm, 0.05 rad): it
  // stood penalised there, not at the sideline spot (x = -3.2 m).
  ASSERT_FALSE(r.tracks.empty());
  EXPECT_DOUBLE_EQ(r.tracks.front().t, 0.0);
  EXPECT_NEAR(r.tracks.front().x, -2.0, 0.01);
  EXPECT_NEAR(r.tracks.front().y, -2.9, 0.03);
  EXPECT_NEAR(r.tracks.front().theta, 1.5708, 0.05);
  EXPECT_NEAR(r.tracks.back().t, 2.0, 1e-9);
  // Then it walks (toward +y).
  EXPECT_GT(r.tracks.back().y - r.tracks.front().y, 0.1);
}

// A robot pushed over that does not get up is moved to its nearest touch
// line after `fallen.sideline_after` s, standing.
TEST(Batch, FallenRobotMovedToTheSideline) {
  const std::string text =
      "name: fall\nseed: 5\ntime_limit: 3.4\ntrials_per_position: 1\nfallen: {sideline_after: 1.5}\n"
      "tracks: {every: 0.1}\n"
      "balls: [{position: 1, x: 3.0, y: -2.0}]\n"
      "setups:\n  - name: s\n    robots:\n"
      "      - {team: 19, player: 2, x: 0.0, y: 1.0, theta: 0.0, behaviour: script,\n"
      "         actions: [{t: 0, action: stand}, {t: 0.5, push: {x: 3.0, y: 0.0}}]}\n";
  const Experiment e = Experiment::parse(text, "fall.yaml");
  const TrialResult r = runTrial(e, 0, behaviourHooks());
  EXPECT_FALSE(r.found);
  ASSERT_EQ(r.robots.size(), 1u);
  EXPECT_GE(r.robots[0].falls, 1);
  // 3.4 s leaves room for one move only: down at ~0.5-1 s, moved 1.5 s
  // later; a second move needs another fall after that and 1.5 s more. (The
  // robot may be moved in the middle of its get-up, which then topples it:
  // as when a referee picks up a robot that is getting up.)
  EXPECT_EQ(r.robots[0].sideline_moves, 1);
  // The sample taken at the move, where the robot was put: on the top touch
  // line (it started at y = +1), standing (torso above kStandHeight is not in
  // the track, but its heading is), facing the field. What the script robot
  // does afterwards is its own business.
  bool moved = false;
  const double play_s = static_cast<double>(playTick(e)) * simswift::kTickSeconds;  // track clock's zero
  for (const TrackSample& p : r.tracks)
    if (std::abs(p.y - 3.0) < 0.02 && std::abs(p.theta + M_PI / 2) < 0.05) {
      moved = true;
      EXPECT_GE(p.t + play_s, 0.5 + 1.5);  // pushed at 0.5 s (scenario clock), then 1.5 s down at least
      break;
    }
  EXPECT_TRUE(moved);
  // The move itself is not walking: a push and a fall cover well under 1.5 m.
  EXPECT_LT(r.robots[0].distance_m, 1.5);
}
