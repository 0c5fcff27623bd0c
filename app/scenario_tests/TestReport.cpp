#include "app/scenario_tests/TestReport.hpp"

#include <cstdio>
#include <sstream>

#include "app/experiment/Figures.hpp"
#include "app/experiment/Files.hpp"
#include "app/experiment/Trial.hpp"

namespace simswift::scenario_tests {

namespace {

std::string f1(double v) { return experiment::fixed(v, 1); }
std::string f2(double v) { return experiment::fixed(v, 2); }
std::string pct(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.0f", 100 * v);
  return b;
}
std::string pval(double p) {
  char b[32];
  if (p < 0.001) std::snprintf(b, sizeof b, "%.1e", p);
  else std::snprintf(b, sizeof b, "%.3f", p);
  return b;
}

}  // namespace

const char* const kTestWallClockHeading = "## Wall clock";

std::string verdictLine(const TestSummary& s) {
  std::string l = std::to_string(s.passed) + "/" + std::to_string(s.runs) + " passed (95 % interval " + pct(s.lo) +
                  "-" + pct(s.hi) + " %), required " + pct(s.required) + " %: " + verdictName(s.verdict);
  if (s.regressed) {
    l += "; regressed against the baseline (" + std::to_string(s.base_passed) + "/" + std::to_string(s.base_runs) +
         " passed there; rate p = " + pval(s.p_rate_adj);
    if (s.time_compared) l += ", time to pass p = " + pval(s.p_time_adj);
    l += ", Holm-adjusted)";
  }
  return l;
}

std::string failureText(const TestFile& f, const TestOptions& opt, const TestSummary& s) {
  std::ostringstream o;
  for (const RunResult& r : s.failures)
    o << "run " << r.run << " (seed " << r.seed << "): " << r.failure << recordingNote(opt, r)
      << "\n  replay: " << replayCommand(f, opt, r) << "\n";
  return o.str();
}

std::string consoleSummary(const TestFile& f, const TestOptions& opt, const std::vector<TestSummary>& tests) {
  std::ostringstream o;
  int ok = 0;
  for (const TestSummary& s : tests) {
    const bool good = s.verdict == TestSummary::Verdict::Passes && !s.regressed;
    ok += good;
    o << (good ? "PASS " : "FAIL ") << s.name << ": " << verdictLine(s) << "\n";
    if (s.compared && !s.regressed)
      o << "     against the baseline: " << s.base_passed << "/" << s.base_runs << " passed there, no regression (rate p = "
        << pval(s.p_rate_adj) << (s.time_compared ? ", time p = " + pval(s.p_time_adj) : std::string()) << ")\n";
    const size_t shown = std::min<size_t>(s.failures.size(), 5);
    for (size_t i = 0; i < shown; ++i) {
      const RunResult& r = s.failures[i];
      o << "     run " << r.run << " (seed " << r.seed << "): " << r.failure << recordingNote(opt, r) << "\n       replay: "
        << replayCommand(f, opt, r) << "\n";
    }
    if (s.failures.size() > shown)
      o << "     ... " << s.failures.size() - shown << " more failing run(s) in the report\n";
  }
  o << ok << " of " << tests.size() << " tests pass" << (opt.short_form ? " (short form)" : "") << "\n";
  return o.str();
}

std::string summaryCsv(const std::vector<TestSummary>& tests, bool baseline) {
  std::ostringstream o;
  o << "test,runs,passed,rate,lo95,hi95,required,verdict,mean_pass_s";
  if (baseline) o << ",base_runs,base_passed,p_rate,p_time,p_rate_holm,p_time_holm,regressed";
  o << "\n";
  for (const TestSummary& s : tests) {
    o << s.name << ',' << s.runs << ',' << s.passed << ',' << f2(s.rate()) << ',' << f2(s.lo) << ',' << f2(s.hi) << ','
      << f2(s.required) << ',' << (s.verdict == TestSummary::Verdict::Undecided ? "undecided" : verdictName(s.verdict))
      << ',' << f2(s.mean_pass_s);
    if (baseline) {
      if (s.compared)
        o << ',' << s.base_runs << ',' << s.base_passed << ',' << pval(s.p_rate) << ','
          << (s.time_compared ? pval(s.p_time) : "") << ',' << pval(s.p_rate_adj) << ','
          << (s.time_compared ? pval(s.p_time_adj) : "") << ',' << (s.regressed ? 1 : 0);
      else
        o << ",,,,,,,";
    }
    o << "\n";
  }
  return o.str();
}

std::string reportMarkdown(const TestFile& f, const TestOptions& opt, const std::vector<TestSummary>& tests,
                           bool figure) {
  std::ostringstream o;
  int runs = 0;
  for (const TestSummary& s : tests) runs += s.runs;
  o << "# Scenario tests: " << f.name << "\n\n";
  o << "File `" << f.source << "`, " << tests.size() << " tests, " << runs << " runs ("
    << (opt.short_form ? "short form" : "full form") << "), seed " << (opt.has_seed ? opt.seed : f.seed)
    << ". A test passes when the lower end of its pass rate's Wilson 95 % interval reaches the required rate, "
       "fails when the upper end is below it, and is undecided otherwise (run more seeds).\n\n";
  o << "| test | passed | rate | 95 % interval | required | verdict | mean time to pass (s) |\n";
  o << "|---|---:|---:|---|---:|---|---:|\n";
  for (const TestSummary& s : tests)
    o << "| " << s.name << " | " << s.passed << "/" << s.runs << " | " << pct(s.rate()) << " % | " << pct(s.lo) << "-"
      << pct(s.hi) << " % | " << pct(s.required) << " % | " << verdictName(s.verdict) << " | " << f1(s.mean_pass_s)
      << " |\n";
  if (figure) o << "\n![pass rates](pass_rates.png)\n";
  if (!opt.baseline.empty()) {
    o << "\n## Against the baseline\n\nBaseline `" << opt.baseline
      << "`. One-sided tests: the pass rate by Fisher's exact test (lower now), the time to pass by Mann-Whitney "
         "(longer now, when both runs have at least two passes); p-values Holm-adjusted over every comparison of "
         "the file; a regression is called below "
      << opt.alpha << ".\n\n";
    o << "| test | now | baseline | p rate | p time | p rate (Holm) | p time (Holm) | regressed |\n";
    o << "|---|---:|---:|---:|---:|---:|---:|---|\n";
    for (const TestSummary& s : tests) {
      if (!s.compared) {
        o << "| " << s.name << " | " << s.passed << "/" << s.runs << " | "
          << (s.changed ? "(redefined since the baseline)" : "(not in the baseline)") << " | | | | | |\n";
        continue;
      }
      o << "| " << s.name << " | " << s.passed << "/" << s.runs << " | " << s.base_passed << "/" << s.base_runs << " | "
        << pval(s.p_rate) << " | " << (s.time_compared ? pval(s.p_time) : "-") << " | " << pval(s.p_rate_adj) << " | "
        << (s.time_compared ? pval(s.p_time_adj) : "-") << " | " << (s.regressed ? "**yes**" : "no") << " |\n";
    }
  }
  bool any = false;
  for (const TestSummary& s : tests) any = any || !s.failures.empty();
  if (any) {
    o << "\n## Failing runs\n\nEach with the first temporal condition that failed and when, and the command that "
         "replays it in one process (add `--overview DIR` for pictures).\n";
    for (const TestSummary& s : tests) {
      if (s.failures.empty()) continue;
      o << "\n### " << s.name << "\n\n";
      for (const RunResult& r : s.failures)
        o << "- run " << r.run << " (seed " << r.seed << "): " << r.failure << recordingNote(opt, r) << ". `"
          << replayCommand(f, opt, r) << "`\n";
    }
  }
  return o.str();
}

std::string wallClockMarkdown(const std::vector<TestSummary>& tests, double batch_wall_s) {
  std::ostringstream o;
  o << "\n" << kTestWallClockHeading << "\n\n| test | simulated s | wall s (per worker) | real-time factor |\n";
  o << "|---|---:|---:|---:|\n";
  double sim = 0, wall = 0;
  for (const TestSummary& s : tests) {
    o << "| " << s.name << " | " << f1(s.sim_s) << " | " << f1(s.wall_s) << " | "
      << (s.wall_s > 0 ? f1(s.sim_s / s.wall_s) + "x" : "-") << " |\n";
    sim += s.sim_s;
    wall += s.wall_s;
  }
  o << "| all | " << f1(sim) << " | " << f1(wall) << " | " << (wall > 0 ? f1(sim / wall) + "x" : "-") << " |\n";
  if (batch_wall_s > 0) o << "\nThe run that completed the folder took " << f1(batch_wall_s) << " s of wall time.\n";
  return o.str();
}

bool plotPassRates(const std::vector<TestSummary>& tests, const std::string& dir, std::string* message) {
  std::ostringstream dat;
  dat << "# index test rate lo hi required\n";
  for (size_t i = 0; i < tests.size(); ++i) {
    const TestSummary& s = tests[i];
    dat << i << ' ' << s.name << ' ' << s.rate() << ' ' << s.lo << ' ' << s.hi << ' ' << s.required << "\n";
  }
  experiment::writeAtomic(dir + "/pass_rates.dat", dat.str());
  const int h = 120 + 40 * static_cast<int>(tests.size());
  std::ostringstream gp;
  gp << "set terminal pngcairo noenhanced size 900," << h << " font 'sans,10'\n"
     << "set output 'pass_rates.png'\n"
     << "set title 'Pass rate per test: 95 % Wilson interval (bar), required rate (red mark)'\n"
     << "set xrange [0:1]\nset xtics 0.1 format '%.0f' scale 1\n"
     << "set format x '%g'\nset xlabel 'pass rate'\n"
     << "set yrange [" << tests.size() - 0.3 << ":-0.7]\nset ytics scale 0\nset grid xtics\nunset key\n"  // first test on top
     << "plot 'pass_rates.dat' using 3:1:4:5:ytic(2) with xerrorbars lc rgb '#1f5fa8' pt 7 lw 2, \\\n"
     << "     '' using 6:1 with points lc rgb '#c0392b' pt 11 ps 2\n";
  experiment::writeAtomic(dir + "/pass_rates.gp", gp.str());
  return experiment::runGnuplot(dir, "pass_rates", "the pass-rate figure", message);
}

}  // namespace simswift::scenario_tests
