#include "app/scenario_tests/TestBatch.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>
#include <sstream>

#include <unistd.h>

#include "app/experiment/Batch.hpp"
#include "app/experiment/Files.hpp"
#include "app/experiment/ForkPool.hpp"
#include "app/experiment/PrivateShm.hpp"
#include "app/experiment/ProgressLine.hpp"
#include "app/experiment/ResultsFolder.hpp"
#include "app/experiment/Trial.hpp"
#include "app/scenario_tests/JUnit.hpp"
#include "app/scenario_tests/TestReport.hpp"

namespace simswift::scenario_tests {

using experiment::BatchError;
using experiment::exists;
using experiment::readFile;
using experiment::trialFile;
using experiment::writeAtomic;

namespace {

std::string timingRow(const RunResult& r) {
  return experiment::fixed(r.sim_s, 3) + "," + experiment::fixed(r.wall_s, 3) + "\n";
}

void readTiming(const std::string& path, RunResult& r) {
  if (!exists(path)) return;
  std::sscanf(readFile(path).c_str(), "%lf,%lf", &r.sim_s, &r.wall_s);
}

RunResult readRun(const std::string& dir, int t) {
  std::string row = readFile(trialFile(dir, t, ".csv"));
  while (!row.empty() && row.back() == '\n') row.pop_back();
  RunResult r = parseResultsRow(row);
  readTiming(trialFile(dir, t, ".timing.csv"), r);
  return r;
}

void writeRun(const std::string& dir, const RunResult& r) {
  writeAtomic(trialFile(dir, r.index, ".timing.csv"), timingRow(r));
  writeAtomic(trialFile(dir, r.index, ".csv"), resultsRow(r));  // last: "done"
}

// A scenario test's run as a ForkJob.
class RunJob : public experiment::ForkJob {
 public:
  RunJob(const TestFile& f, const TestOptions& opt, experiment::ProgressLine& progress)
      : f_(f), opt_(opt), progress_(progress) {}
  std::string logFile(int t) const override { return trialFile(opt_.out_dir, t, ".log"); }
  void run(int t) const override {
    const RunSpec s = runSpec(f_, opt_.short_form, t, opt_.seed, opt_.has_seed);
    // Launched programs' logs and setups: DIR/trials/<run>/.
    RunResult probe;
    probe.test = f_.tests[s.test].name;
    probe.run = s.run;
    const std::string rec = opt_.record == TestOptions::Record::None ? "" : recordingPath(opt_, probe);
    const RunResult r = runTest(f_, s, opt_.out_dir + "/trials/" + std::to_string(t), "", rec);
    // --record failures: a passing run's recording is not kept.
    if (!rec.empty() && r.passed && opt_.record == TestOptions::Record::Failures) std::remove(rec.c_str());
    writeRun(opt_.out_dir, r);
  }
  bool done(int t) const override { return experiment::trialDone(opt_.out_dir, t); }
  void finished(int t, double) override {
    const RunResult r = readRun(opt_.out_dir, t);
    char what[400];
    std::snprintf(what, sizeof what, "%s run %d (seed %llu): %s at %.2f s%s%s%s", r.test.c_str(), r.run,
                  static_cast<unsigned long long>(r.seed), r.passed ? "passed" : "failed",
                  r.passed ? r.decided_s : r.failure_s, r.passed ? "" : ": ", r.failure.c_str(),
                  recordingNote(opt_, r).c_str());
    progress_.step(what);
  }
  // A run whose process died (a crash, a hang ended by the watchdog, a
  // launched program that killed it) is a failing run, recorded as such so
  // the folder still gets its verdicts; its log stays. Delete its
  // trial_NNNNNN.csv to run it again.
  void failed(int t, const std::string& why) override {
    progress_.fail(t, why);
    const RunSpec s = runSpec(f_, opt_.short_form, t, opt_.seed, opt_.has_seed);
    RunResult r;
    r.index = t;
    r.test = f_.tests[s.test].name;
    r.run = s.run;
    r.seed = s.seed;
    r.failure = "the run's process failed (" + why.substr(0, why.find(':')) + ")";  // no pid or path
    writeRun(opt_.out_dir, r);
  }

 private:
  const TestFile& f_;
  const TestOptions& opt_;
  experiment::ProgressLine& progress_;
};

// Launched programs open fixed names: each worker gets its own /dev/shm,
// or the runs go one at a time.
bool privateShmFor(const TestFile& f, int* jobs) {
  bool launches = false;
  for (const ScenarioTest& t : f.tests)
    for (const runner::RobotSpec& r : t.scenario.robots) launches = launches || r.launch.launched();
  if (!launches) return false;
  std::string why;
  const bool ok = experiment::privateShmAvailable(&why);
  if (!ok && *jobs > 1) {
    std::fprintf(stderr,
                 "simswift: this machine gives no private /dev/shm to a run (%s); launched robot programs share "
                 "names, so the runs go one at a time\n",
                 why.c_str());
    *jobs = 1;
  }
  return ok;
}

std::vector<RunResult> readBaseline(const std::string& dir) {
  const std::string path = dir + "/results.csv";
  if (!exists(path))
    throw experiment::BatchInputError("--baseline " + dir + ": no results.csv (the folder of a finished simswift test run)");
  std::istringstream in(readFile(path));
  std::string line;
  std::vector<RunResult> out;
  int n = 0;
  while (std::getline(in, line)) {
    if (n++ == 0) {
      if (line + "\n" != resultsHeader())
        throw experiment::BatchInputError("--baseline " + path + ": not a simswift test results file (header " + line + ")");
      continue;
    }
    if (line.empty()) continue;
    try {
      out.push_back(parseResultsRow(line));
    } catch (const std::exception& e) {
      throw experiment::BatchInputError("--baseline " + path + ":" + std::to_string(n) + ": " + e.what());
    }
  }
  return out;
}

// Every run present: results.csv, summary.csv, report.md, the figure, junit.xml.
void assemble(const TestFile& f, const TestOptions& opt, int total, TestOutcome& out, double wall_s) {
  std::vector<RunResult> results;
  std::string csv = resultsHeader();
  for (int t = 0; t < total; ++t) {
    results.push_back(readRun(opt.out_dir, t));
    csv += resultsRow(results.back());
  }
  writeAtomic(opt.out_dir + "/results.csv", csv);
  out.tests = summarise(f, results);
  if (!opt.baseline.empty()) {
    // Tests redefined since the baseline (same name, another entry) are not compared.
    std::set<std::string> changed;
    const std::string held = opt.baseline + "/tests.yaml";
    if (exists(held)) {
      const std::map<std::string, std::string> before = testDefinitions(readFile(held), held);
      for (const ScenarioTest& t : f.tests) {
        auto it = before.find(t.name);
        if (it != before.end() && it->second != t.definition) changed.insert(t.name);
      }
    }
    compareWithBaseline(out.tests, results, readBaseline(opt.baseline), opt.alpha, changed);
  }
  writeAtomic(opt.out_dir + "/summary.csv", summaryCsv(out.tests, !opt.baseline.empty()));
  std::string figure_note;
  const bool figure = plotPassRates(out.tests, opt.out_dir, &figure_note);
  writeAtomic(opt.out_dir + "/report.md", reportMarkdown(f, opt, out.tests, figure) + wallClockMarkdown(out.tests, wall_s));
  const std::string xml = junitXml(f, opt, out.tests);
  writeAtomic(opt.out_dir + "/junit.xml", xml);
  if (!opt.junit.empty()) writeAtomic(opt.junit, xml);
  out.assembled = true;
  out.exit_code = exitCode(out.tests);
  std::ostringstream m;
  m << consoleSummary(f, opt, out.tests);
  if (!figure_note.empty()) m << figure_note << "\n";
  m << "report: " << opt.out_dir << "/report.md (results.csv, summary.csv, junit.xml"
    << (opt.junit.empty() ? "" : ", also " + opt.junit) << ")";
  out.message = m.str();
}

}  // namespace

std::string folderText(const TestFile& f, const TestOptions& opt) {
  std::string t = f.text;
  if (!t.empty() && t.back() != '\n') t += '\n';
  t += "# simswift test: " + std::string(opt.short_form ? "--short" : "full form");
  if (opt.has_seed) t += " --seed " + std::to_string(opt.seed);
  if (!opt.only.empty()) {
    // The tests kept, in the file's order (--only b,a and a,b are one run).
    t += " --only ";
    for (size_t k = 0; k < f.tests.size(); ++k) t += (k ? "," : "") + f.tests[k].name;
  }
  return t + "\n";
}

std::string recordingPath(const TestOptions& opt, const RunResult& r) {
  std::string name = r.test;
  for (char& c : name)  // a file name whatever the test is called
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return opt.out_dir + "/recordings/" + name + "_run" + std::to_string(r.run) + ".mcap";
}

std::string recordingNote(const TestOptions& opt, const RunResult& r) {
  if (opt.record == TestOptions::Record::None || r.passed) return "";
  const std::string path = recordingPath(opt, r);
  if (access(path.c_str(), R_OK) != 0) return "";  // a resumed folder's run recorded before --record
  // The viewer opened at the failing moment (docs/viewer.md).
  char at[32];
  std::snprintf(at, sizeof at, "%.3f", r.failure_s);
  return " (recording " + path + ") (at the failure: simswift view " + path + " --at " + at + ")";
}

std::string replayCommand(const TestFile& f, const TestOptions& opt, const RunResult& r) {
  std::string c = "simswift test " + f.source + " --test " + r.test + " --trial " + std::to_string(r.run);
  if (opt.has_seed) c += " --seed " + std::to_string(opt.seed);
  return c;
}

TestOutcome runTests(const TestFile& f, const TestOptions& opt) {
  if (opt.shards < 1 || opt.shard < 1 || opt.shard > opt.shards) throw BatchError("bad shard");
  checkPlacements(f, opt.short_form, opt.seed, opt.has_seed);
  if (!opt.baseline.empty()) (void)readBaseline(opt.baseline);  // a bad baseline before any run
  const experiment::FolderLock lock = experiment::claimFolder(folderText(f, opt), f.source, opt.out_dir, "tests.yaml");
  const int total = countRuns(f, opt.short_form);
  TestOutcome out;
  std::vector<int> todo;
  for (int t = opt.shard - 1; t < total; t += opt.shards) {
    ++out.runs;
    if (experiment::trialDone(opt.out_dir, t)) ++out.already;
    else todo.push_back(t);
  }
  int jobs = opt.jobs > 0 ? opt.jobs : static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
  jobs = std::max(1, std::min<int>(jobs, static_cast<int>(std::max<size_t>(1, todo.size()))));
  experiment::ProgressLine progress;
  progress.total = out.runs;
  progress.done = out.already;
  progress.lines = opt.progress_lines;
  if (progress.lines && out.already > 0)
    std::fprintf(stderr, "%s: %d of %d runs already done, resuming\n", opt.out_dir.c_str(), out.already, out.runs);
  std::fflush(stdout);
  std::fflush(stderr);
  const bool private_shm = privateShmFor(f, &jobs);
  RunJob job(f, opt, progress);
  const experiment::ForkRun run = experiment::runForked(job, todo, jobs, private_shm);
  progress.end();
  out.ran = run.ran;
  out.failed = run.failed;
  out.interrupted = run.interrupted;
  std::ostringstream m;
  if (out.interrupted) {
    m << "interrupted: " << out.already + out.ran << " of " << out.runs << " runs kept in " << opt.out_dir
      << "; run the same command again to continue";
    out.message = m.str();
    out.exit_code = 130;
    return out;
  }
  bool all = true;
  for (int t = 0; t < total && all; ++t) all = experiment::trialDone(opt.out_dir, t);
  if (all) {
    assemble(f, opt, total, out, run.wall_s);
    if (out.failed)
      out.message = std::to_string(out.failed) + " run(s) failed in their process (counted as failing; logs in " +
                    opt.out_dir + "/trials)\n" + out.message;
    return out;
  }
  m << "shard " << opt.shard << "/" << opt.shards << ": " << out.already + out.ran + out.failed << " runs in "
    << opt.out_dir << "; join the shards with `simswift test FILE --merge DIR... --out DIR`";
  out.message = m.str();
  return out;
}

TestOutcome mergeTests(const TestFile& f, const std::vector<std::string>& dirs, const TestOptions& opt) {
  const std::string text = folderText(f, opt);
  const experiment::FolderLock lock = experiment::claimFolder(text, f.source, opt.out_dir, "tests.yaml");
  const int total = countRuns(f, opt.short_form);
  for (const std::string& d : dirs) {
    if (!exists(d + "/tests.yaml") || readFile(d + "/tests.yaml") != text)
      throw experiment::BatchInputError(d + " is not a shard of " + f.source + " with these options (its tests.yaml differs)");
    for (int t = 0; t < total; ++t)
      if (experiment::trialDone(d, t) && !experiment::trialDone(opt.out_dir, t)) {
        if (exists(trialFile(d, t, ".timing.csv")))
          writeAtomic(trialFile(opt.out_dir, t, ".timing.csv"), readFile(trialFile(d, t, ".timing.csv")));
        writeAtomic(trialFile(opt.out_dir, t, ".csv"), readFile(trialFile(d, t, ".csv")));
      }
  }
  TestOutcome out;
  out.runs = total;
  for (int t = 0; t < total; ++t) out.already += experiment::trialDone(opt.out_dir, t);
  if (out.already == total) {
    assemble(f, opt, total, out, 0);
  } else {
    out.message = std::to_string(out.already) + " of " + std::to_string(total) + " runs in " + opt.out_dir +
                  "; the other shards are still missing";
    out.exit_code = 1;
  }
  return out;
}

}  // namespace simswift::scenario_tests
