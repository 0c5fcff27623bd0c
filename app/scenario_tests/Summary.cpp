#include "app/scenario_tests/Summary.hpp"

#include <map>

#include "app/experiment/Statistics.hpp"

namespace simswift::scenario_tests {

namespace stats = experiment::stats;

const char* verdictName(TestSummary::Verdict v) {
  switch (v) {
    case TestSummary::Verdict::Passes: return "passes";
    case TestSummary::Verdict::Fails: return "fails";
    case TestSummary::Verdict::Undecided: return "undecided: run more seeds";
  }
  return "?";
}

namespace {

std::vector<double> passTimes(const std::vector<RunResult>& rs, const std::string& test) {
  std::vector<double> t;
  for (const RunResult& r : rs)
    if (r.test == test && r.passed) t.push_back(r.decided_s);
  return t;
}

// A run of this run and the baseline's run of the same test on the same
// seed: the same placement and noise (run seeds derive from the file seed,
// the test's name and the run index: TestFile.hpp runSeed).
struct Pair {
  const RunResult* now = nullptr;
  const RunResult* base = nullptr;
};

std::vector<Pair> pairsBySeed(const std::vector<RunResult>& current, const std::vector<RunResult>& baseline,
                              const std::string& test) {
  std::map<uint64_t, const RunResult*> base;
  for (const RunResult& r : baseline)
    if (r.test == test) base.emplace(r.seed, &r);
  std::vector<Pair> out;
  for (const RunResult& r : current)
    if (r.test == test)
      if (auto it = base.find(r.seed); it != base.end()) {
        out.push_back({&r, it->second});
        base.erase(it);  // each baseline run in one pair
      }
  return out;
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0 : s / static_cast<double>(v.size());
}

}  // namespace

std::vector<TestSummary> summarise(const TestFile& f, const std::vector<RunResult>& results) {
  std::vector<TestSummary> out;
  std::map<std::string, size_t> at;
  for (const ScenarioTest& t : f.tests) {
    at[t.name] = out.size();
    TestSummary s;
    s.name = t.name;
    s.required = t.required;
    out.push_back(s);
  }
  std::vector<RunResult> sorted = results;
  std::sort(sorted.begin(), sorted.end(), [](const RunResult& a, const RunResult& b) { return a.index < b.index; });
  for (const RunResult& r : sorted) {
    auto it = at.find(r.test);
    if (it == at.end()) continue;
    TestSummary& s = out[it->second];
    ++s.runs;
    if (r.passed) ++s.passed;
    else s.failures.push_back(r);
    s.sim_s += r.sim_s;
    s.wall_s += r.wall_s;
  }
  for (TestSummary& s : out) {
    const stats::Interval w = stats::wilson(s.passed, s.runs);
    s.lo = w.lo;
    s.hi = w.hi;
    s.verdict = s.lo >= s.required   ? TestSummary::Verdict::Passes
                : s.hi < s.required ? TestSummary::Verdict::Fails
                                    : TestSummary::Verdict::Undecided;
    s.mean_pass_s = mean(passTimes(sorted, s.name));
  }
  return out;
}

void compareWithBaseline(std::vector<TestSummary>& tests, const std::vector<RunResult>& current,
                         const std::vector<RunResult>& baseline, double alpha, const std::set<std::string>& changed) {
  std::map<std::string, std::pair<int, int>> base;  // runs, passed
  for (const RunResult& r : baseline) {
    auto& b = base[r.test];
    ++b.first;
    b.second += r.passed;
  }
  std::vector<double> raw;
  std::vector<std::pair<size_t, bool>> which;  // test, is-time (else rate)
  for (size_t i = 0; i < tests.size(); ++i) {
    TestSummary& s = tests[i];
    auto it = base.find(s.name);
    if (it == base.end() || it->second.first == 0 || s.runs == 0) continue;
    if (changed.count(s.name)) {
      s.changed = true;  // another test under the same name: nothing to compare
      continue;
    }
    s.compared = true;
    s.base_runs = it->second.first;
    s.base_passed = it->second.second;
    const std::vector<double> now_t = passTimes(current, s.name), base_t = passTimes(baseline, s.name);
    s.base_mean_pass_s = mean(base_t);
    const std::vector<Pair> pairs = pairsBySeed(current, baseline, s.name);
    s.pairs = static_cast<int>(pairs.size());
    if (!pairs.empty()) {
      // Paired: McNemar on the discordant pairs; Wilcoxon on the times of
      // the pairs that passed on both sides (now - before, s).
      int worse = 0, better = 0;
      std::vector<double> slower;
      for (const Pair& pr : pairs) {
        worse += pr.base->passed && !pr.now->passed;
        better += !pr.base->passed && pr.now->passed;
        if (pr.base->passed && pr.now->passed) slower.push_back(pr.now->decided_s - pr.base->decided_s);
      }
      s.p_rate = stats::mcnemarWorse(worse, better);
      raw.push_back(s.p_rate);
      which.push_back({i, false});
      // Equal times say nothing (the same program on the same seed gives
      // them all): compared when at least two pairs differ.
      const stats::SignedRank w = stats::wilcoxonGreater(slower);
      if (w.n >= 2) {
        s.time_compared = true;
        s.p_time = w.p;
        raw.push_back(s.p_time);
        which.push_back({i, true});
      }
      continue;
    }
    // Independent. Rows: now, baseline; columns: passed, failed.
    s.p_rate = stats::fisherLess(s.passed, s.runs - s.passed, s.base_passed, s.base_runs - s.base_passed);
    raw.push_back(s.p_rate);
    which.push_back({i, false});
    // Times that all tie (a test decided only at its time limit) say
    // nothing: left out of the family rather than diluting it.
    bool all_tie = true;
    for (const std::vector<double>* v : {&now_t, &base_t})
      for (double x : *v) all_tie = all_tie && x == (now_t.empty() ? x : now_t.front());
    if (now_t.size() >= 2 && base_t.size() >= 2 && !all_tie) {
      s.time_compared = true;
      s.p_time = stats::mannWhitneyGreater(now_t, base_t).p;
      raw.push_back(s.p_time);
      which.push_back({i, true});
    }
  }
  const std::vector<double> adj = stats::holm(raw);
  for (size_t k = 0; k < which.size(); ++k) {
    TestSummary& s = tests[which[k].first];
    (which[k].second ? s.p_time_adj : s.p_rate_adj) = adj[k];
    if (adj[k] < alpha) s.regressed = true;
  }
}

int exitCode(const std::vector<TestSummary>& tests) {
  for (const TestSummary& s : tests)
    if (s.verdict != TestSummary::Verdict::Passes || s.regressed) return 1;
  return 0;
}

}  // namespace simswift::scenario_tests
