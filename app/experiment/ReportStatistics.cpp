// The report's statistics section (Report.hpp): intervals per cell and per
// component, and tests of the differences between components on the same
// positions (app/experiment/Statistics.hpp), said in words.
#include <map>
#include <sstream>

#include "app/experiment/Report.hpp"
#include "app/experiment/Statistics.hpp"
#include "common/random/DeriveSeed.hpp"

namespace simswift::experiment {

namespace {

std::string pct(double v) { return fixed(100.0 * v, 0); }
std::string interval(const stats::Interval& i, int decimals, double scale = 1.0, const std::string& unit = "") {
  return "[" + fixed(i.lo * scale, decimals) + ", " + fixed(i.hi * scale, decimals) + "]" + unit;
}
std::string pValue(double p) { return p < 0.001 ? "< 0.001" : fixed(p, 3); }

// A cell: the trials that ran of one setup at one position (position 0: all).
struct Cell {
  int found = 0, tests = 0;
  std::vector<double> times;  // s, of the finds
  double meanTime() const {
    double m = 0;
    for (double t : times) m += t / static_cast<double>(times.size());
    return m;
  }
};

Cell cell(const std::vector<TrialResult>& results, const std::string& setup, int position) {
  Cell c;
  for (const TrialResult& r : results) {
    if (r.setup != setup || (position && r.position != position) || !r.failed.empty()) continue;
    ++c.tests;
    if (r.found) {
      ++c.found;
      c.times.push_back(r.seconds);
    }
  }
  return c;
}

// The bootstrap's seed: a pure function of the experiment and the cell.
uint64_t cellSeed(const Experiment& e, size_t setup, int position) {
  using common::random::deriveSeed;
  return deriveSeed(deriveSeed(deriveSeed(e.seed, common::random::seed_tag::kReportBootstrap), setup),
                    static_cast<uint64_t>(position));
}

std::string listPositions(const std::vector<int>& ps) {
  std::string s;
  for (size_t i = 0; i < ps.size(); ++i)
    s += (i == 0 ? "" : i + 1 == ps.size() ? " and " : ", ") + std::to_string(ps[i]);
  return s;
}

}  // namespace

std::string statisticsSection(const Experiment& e, const std::vector<TrialResult>& results) {
  std::ostringstream s;
  s << "## Statistics\n\n"
    << "95 % intervals: find rates by the Wilson score interval; mean find times by a percentile bootstrap over "
       "the finds (2000 resamples, seeded from the experiment's seed and the cell, so every run prints the same "
       "numbers). Differences between two setups on the same positions: Fisher's exact test for the find rate "
       "and the Mann-Whitney U test for the find times (both two-sided). With 5-10 trials per cell most "
       "per-position differences cannot be told from chance; the pooled rows say more.\n\n";
  for (size_t si = 0; si < e.setups.size(); ++si) {
    const std::string& name = e.setups[si].name;
    s << "### `" << name << "`\n\n| Position | Found | Find rate (95 % CI) | Mean find s (95 % CI) |\n"
      << "|---|---:|---:|---:|\n";
    // One row: a position (0: all of them).
    auto row = [&](int position, const std::string& label) {
      const Cell c = cell(results, name, position);
      const stats::Interval r = stats::wilson(c.found, c.tests);
      s << "| " << label << " | " << c.found << "/" << c.tests << " | "
        << (c.tests ? pct(static_cast<double>(c.found) / c.tests) + " % " + interval(r, 0, 100.0, " %") : "-")
        << " | ";
      if (c.times.empty()) {
        s << "- |\n";
        return;
      }
      s << fixed(c.meanTime(), 2) << " " << interval(stats::bootstrapMean(c.times, cellSeed(e, si, position)), 2) << " |\n";
    };
    for (const BallPosition& b : e.balls) row(b.number, std::to_string(b.number));
    row(0, "all");
    s << "\n";
  }

  // Every pair of setups, position by position and pooled.
  for (size_t a = 0; a < e.setups.size(); ++a)
    for (size_t b = a + 1; b < e.setups.size(); ++b) {
      const std::string& na = e.setups[a].name;
      const std::string& nb = e.setups[b].name;
      s << "### `" << na << "` against `" << nb << "`\n\n"
        << "| Position | Found `" << na << "` | Found `" << nb << "` | Fisher p | Mean s `" << na << "` | Mean s `"
        << nb << "` | Mann-Whitney p |\n|---|---:|---:|---:|---:|---:|---:|\n";
      std::vector<int> more_a, more_b, faster_a, faster_b;
      auto row = [&](int position, const std::string& label) {
        const Cell ca = cell(results, na, position), cb = cell(results, nb, position);
        if (!ca.tests || !cb.tests) return;
        const double pf = stats::fisherExact(ca.found, ca.tests - ca.found, cb.found, cb.tests - cb.found);
        s << "| " << label << " | " << ca.found << "/" << ca.tests << " | " << cb.found << "/" << cb.tests << " | "
          << pValue(pf) << " | ";
        const double ma = ca.meanTime(), mb = cb.meanTime();
        s << (ca.times.empty() ? "-" : fixed(ma, 2)) << " | " << (cb.times.empty() ? "-" : fixed(mb, 2)) << " | ";
        double pm = 1;
        if (!ca.times.empty() && !cb.times.empty()) {
          pm = stats::mannWhitney(ca.times, cb.times).p;
          s << pValue(pm) << " |\n";
        } else {
          s << "- |\n";
        }
        if (position == 0) return;
        const double ra = static_cast<double>(ca.found) / ca.tests, rb = static_cast<double>(cb.found) / cb.tests;
        if (pf < 0.05) (ra > rb ? more_a : more_b).push_back(position);
        if (pm < 0.05 && !ca.times.empty() && !cb.times.empty()) (ma < mb ? faster_a : faster_b).push_back(position);
      };
      for (const BallPosition& p : e.balls) row(p.number, std::to_string(p.number));
      row(0, "all");
      s << "\n";
      auto say = [&](const std::vector<int>& ps, const std::string& who, const std::string& what) {
        if (!ps.empty())
          s << "- `" << who << "` " << what << " at position" << (ps.size() > 1 ? "s " : " ") << listPositions(ps)
            << " (p < 0.05).\n";
      };
      say(more_a, na, "finds more balls than `" + nb + "`");
      say(more_b, nb, "finds more balls than `" + na + "`");
      say(faster_a, na, "finds the ball sooner than `" + nb + "`");
      say(faster_b, nb, "finds the ball sooner than `" + na + "`");
      if (more_a.empty() && more_b.empty() && faster_a.empty() && faster_b.empty())
        s << "- No position shows a difference at p < 0.05.\n";
      const Cell ca = cell(results, na, 0), cb = cell(results, nb, 0);
      if (ca.tests && cb.tests) {
        const double pf = stats::fisherExact(ca.found, ca.tests - ca.found, cb.found, cb.tests - cb.found);
        s << "- Over all positions: find rates " << ca.found << "/" << ca.tests << " and " << cb.found << "/"
          << cb.tests << ", Fisher p " << pValue(pf) << (pf < 0.05 ? " (a difference larger than chance)" : " (within chance)");
        if (!ca.times.empty() && !cb.times.empty()) {
          const double pm = stats::mannWhitney(ca.times, cb.times).p;
          s << "; find times Mann-Whitney p " << pValue(pm)
            << (pm < 0.05 ? " (a difference larger than chance)" : " (within chance)");
        }
        s << ".\n";
      }
      s << "\n";
    }
  return s.str();
}

}  // namespace simswift::experiment
