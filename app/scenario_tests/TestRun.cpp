#include "app/scenario_tests/TestRun.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "app/experiment/Csv.hpp"
#include "app/experiment/Trial.hpp"
#include "sim/record/Recorder.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Errors.hpp"
#include "sim/runner/Runner.hpp"

namespace simswift::scenario_tests {

namespace {

// One record per line (Csv.hpp): a failure text's line breaks become spaces.
std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

const char* kSideGoal[2] = {"the goal blue defends (-x)", "the goal red defends (+x)"};

void play(const ScenarioTest& test, const std::string& source, runner::Scenario sc, RunResult& res,
          record::Recorder* rec) {
  runner::Runner run(sc);
  // The robot programs' steps on this thread (as an experiment's trials:
  // the same results as named threads; one run per core).
  run.programs().setThreading(agent::program::Threading::Inline);
  run.start();
  if (rec) {
    run.addObserver(rec);
    rec->begin(run);
  }
  bool in_goal[2] = {false, false};
  ConditionRun cond(test.pass, test.field);
  const int64_t ticks = run.world().ticksIn(test.time_limit);
  const double tick_s = run.world().tickSeconds();
  Truth truth = observe(run, 0.0, nullptr);
  Verdict3 v = cond.update(truth);  // the start counts: an invariant already broken, a goal already met
  int64_t k = 0;
  while (k < ticks && v == Verdict3::Pending) {
    run.tick();
    ++k;
    truth = observe(run, static_cast<double>(k) * tick_s, &truth);
    for (int side = 0; side < 2 && rec; ++side) {
      const bool now = truth.has_ball && ballInGoal(truth, test.field, side);
      if (now && !in_goal[side]) rec->event(record::LogLevel::Info, "goal", std::string("goal: the ball in ") + kSideGoal[side]);
      in_goal[side] = now;
    }
    v = cond.update(truth);
  }
  if (v == Verdict3::Pending) v = cond.finish(truth);
  res.passed = v == Verdict3::True;
  res.decided_s = cond.decidedAt();
  if (!res.passed) {
    res.failure = cond.failure();
    res.failure_s = cond.failureTime();
  }
  if (rec) {
    char when[64];
    std::snprintf(when, sizeof when, " at %.2f s", res.passed ? res.decided_s : res.failure_s);
    rec->event(res.passed ? record::LogLevel::Info : record::LogLevel::Error, "verdict",
               test.name + (res.passed ? ": passed" : ": failed") + when + (res.passed ? "" : ": " + res.failure),
               source, test.line);
  }
  for (const RobotTruth& r : truth.robots) res.falls += r.falls;
  res.sim_s = static_cast<double>(k) * tick_s;
}

}  // namespace

RunResult runTest(const TestFile& f, const RunSpec& spec, const std::string& program_logs,
                  const std::string& overview_dir, const std::string& record_path) {
  using Clock = std::chrono::steady_clock;  // wall clock: reporting only
  const auto wall0 = Clock::now();
  const ScenarioTest& test = f.tests.at(spec.test);
  RunResult res;
  res.index = spec.index;
  res.test = test.name;
  res.run = spec.run;
  res.seed = spec.seed;
  runner::Scenario sc = runScenario(test, spec.seed);
  if (!program_logs.empty()) sc.program_logs = program_logs;
  if (!overview_dir.empty()) {
    sc.camera.overview.enabled = true;
    sc.camera.overview.dir = overview_dir;
  }
  for (runner::RobotSpec& r : sc.robots)
    if (r.body == bridge::BodyInterface::Lola) r.lola_socket.clear();  // private to this process
  std::unique_ptr<record::Recorder> rec;
  if (!record_path.empty()) {
    std::filesystem::create_directories(std::filesystem::path(record_path).parent_path());
    rec = std::make_unique<record::Recorder>(record_path);
  }
  try {
    play(test, f.source, sc, res, rec.get());
  } catch (const runner::ProgramError& err) {
    if (rec) rec->event(record::LogLevel::Error, "verdict", std::string("robot program failed: ") + err.what());
    const std::string name = res.test;
    const int run = res.run;
    res = RunResult{};
    res.index = spec.index;
    res.test = name;
    res.run = run;
    res.seed = spec.seed;
    res.failure = "robot program failed: " + err.brief;
    std::fprintf(stderr, "%s run %d failed: %s\n", name.c_str(), run, err.what());
  }
  if (rec) rec->finish();
  res.wall_s = std::chrono::duration<double>(Clock::now() - wall0).count();
  return res;
}

std::string resultsHeader() { return "run,test,test_run,seed,passed,decided_s,failure_s,falls,failure\n"; }

std::string resultsRow(const RunResult& r) {
  std::ostringstream o;
  o << r.index << ',' << r.test << ',' << r.run << ',' << r.seed << ',' << (r.passed ? 1 : 0) << ','
    << experiment::fixed(r.decided_s, 3) << ',' << (r.passed ? "" : experiment::fixed(r.failure_s, 3)) << ','
    << r.falls << ',' << experiment::csvField(oneLine(r.failure)) << '\n';
  return o.str();
}

RunResult parseResultsRow(const std::string& line) {
  const std::vector<std::string> c = experiment::splitCsv(line);
  if (c.size() != 9) throw std::runtime_error("a results row has 9 fields, got " + std::to_string(c.size()));
  RunResult r;
  try {
    r.index = std::stoi(c[0]);
    r.test = c[1];
    r.run = std::stoi(c[2]);
    r.seed = std::stoull(c[3]);
    r.passed = c[4] == "1";
    r.decided_s = std::stod(c[5]);
    r.failure_s = c[6].empty() ? 0 : std::stod(c[6]);
    r.falls = std::stoi(c[7]);
  } catch (const std::exception&) {
    throw std::runtime_error("a results row with a bad number: " + line);
  }
  r.failure = c[8];
  return r;
}

void checkPlacements(const TestFile& f, bool short_form, uint64_t seed_override, bool has_override) {
  const int n = countRuns(f, short_form);
  for (int i = 0; i < n; ++i) {
    const RunSpec s = runSpec(f, short_form, i, seed_override, has_override);
    const ScenarioTest& t = f.tests[s.test];
    const runner::Scenario sc = runScenario(t, s.seed);
    const std::string where = f.source + ":" + std::to_string(t.line) + ": tests[" + std::to_string(s.test) + "] (" +
                              t.name + "), run " + std::to_string(s.run) + " (seed " + std::to_string(s.seed) + "): ";
    try {
      sc.checkAgainstField(t.field);
    } catch (const ConfigError& e) {
      throw ConfigError(where + "its fuzzed placement: " + e.what());
    }
    try {
      runner::checkRobotsApart(sc);
    } catch (const ConfigError& e) {
      throw ConfigError(where + "its fuzzed placement: " + e.what() + ": narrow the fuzz or move them apart");
    }
  }
}

}  // namespace simswift::scenario_tests
