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
       "and the Mann-Whitney U test for the find times (both two-sided), Holm-adjusted over all of them. With "
       "5-10 trials per cell most per-position differences cannot be told from chance; the pooled rows say "
       "more.\n\n";
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

  // Every pair of setups, position by position and pooled: every test of
  // them first, so that all are one family for Holm's adjustment.
  struct Row {
    std::string label;
    int position = 0;  // 0: all positions
    Cell ca, cb;
    double pf = 1, pm = 1;          // raw, two-sided
    double pf_adj = 1, pm_adj = 1;  // Holm-adjusted over the section
    bool timed = false;             // both have finds: times compared
  };
  std::vector<std::vector<Row>> pair_rows;
  std::vector<double> raw;
  for (size_t a = 0; a < e.setups.size(); ++a)
    for (size_t b = a + 1; b < e.setups.size(); ++b) {
      std::vector<Row> rows;
      auto add = [&](int position, const std::string& label) {
        Row r;
        r.label = label;
        r.position = position;
        r.ca = cell(results, e.setups[a].name, position);
        r.cb = cell(results, e.setups[b].name, position);
        if (!r.ca.tests || !r.cb.tests) return;
        r.pf = stats::fisherExact(r.ca.found, r.ca.tests - r.ca.found, r.cb.found, r.cb.tests - r.cb.found);
        raw.push_back(r.pf);
        r.timed = !r.ca.times.empty() && !r.cb.times.empty();
        if (r.timed) {
          r.pm = stats::mannWhitney(r.ca.times, r.cb.times).p;
          raw.push_back(r.pm);
        }
        rows.push_back(r);
      };
      for (const BallPosition& p : e.balls) add(p.number, std::to_string(p.number));
      add(0, "all");
      pair_rows.push_back(rows);
    }
  const std::vector<double> adj = stats::holm(raw);
  size_t next = 0;
  for (std::vector<Row>& rows : pair_rows)
    for (Row& r : rows) {
      r.pf_adj = adj[next++];
      if (r.timed) r.pm_adj = adj[next++];
    }
  if (!raw.empty())
    s << "The differences below are " << raw.size() << " tests in all (every pair of setups, each position and "
      << "all positions, find rate and find time): their p-values are Holm-adjusted over all " << raw.size()
      << ", and a difference is called larger than chance when its adjusted p is below 0.05, so that of a "
         "report with no real difference at most 5 % call one.\n\n";

  size_t pair_index = 0;
  for (size_t a = 0; a < e.setups.size(); ++a)
    for (size_t b = a + 1; b < e.setups.size(); ++b) {
      const std::string& na = e.setups[a].name;
      const std::string& nb = e.setups[b].name;
      const std::vector<Row>& rows = pair_rows[pair_index++];
      s << "### `" << na << "` against `" << nb << "`\n\n"
        << "| Position | Found `" << na << "` | Found `" << nb << "` | Fisher p | (Holm) | Mean s `" << na
        << "` | Mean s `" << nb << "` | Mann-Whitney p | (Holm) |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
      std::vector<int> more_a, more_b, faster_a, faster_b;
      const Row* all = nullptr;
      for (const Row& r : rows) {
        const Cell& ca = r.ca;
        const Cell& cb = r.cb;
        const double ma = ca.meanTime(), mb = cb.meanTime();
        s << "| " << r.label << " | " << ca.found << "/" << ca.tests << " | " << cb.found << "/" << cb.tests << " | "
          << pValue(r.pf) << " | " << pValue(r.pf_adj) << " | " << (ca.times.empty() ? "-" : fixed(ma, 2)) << " | "
          << (cb.times.empty() ? "-" : fixed(mb, 2)) << " | "
          << (r.timed ? pValue(r.pm) + " | " + pValue(r.pm_adj) : std::string("- | -")) << " |\n";
        if (r.position == 0) {
          all = &r;
          continue;
        }
        const double ra = static_cast<double>(ca.found) / ca.tests, rb = static_cast<double>(cb.found) / cb.tests;
        if (r.pf_adj < 0.05) (ra > rb ? more_a : more_b).push_back(r.position);
        if (r.timed && r.pm_adj < 0.05) (ma < mb ? faster_a : faster_b).push_back(r.position);
      }
      s << "\n";
      auto say = [&](const std::vector<int>& ps, const std::string& who, const std::string& what) {
        if (!ps.empty())
          s << "- `" << who << "` " << what << " at position" << (ps.size() > 1 ? "s " : " ") << listPositions(ps)
            << " (Holm-adjusted p < 0.05).\n";
      };
      say(more_a, na, "finds more balls than `" + nb + "`");
      say(more_b, nb, "finds more balls than `" + na + "`");
      say(faster_a, na, "finds the ball sooner than `" + nb + "`");
      say(faster_b, nb, "finds the ball sooner than `" + na + "`");
      if (more_a.empty() && more_b.empty() && faster_a.empty() && faster_b.empty())
        s << "- No position shows a difference at Holm-adjusted p < 0.05.\n";
      if (all) {
        s << "- Over all positions: find rates " << all->ca.found << "/" << all->ca.tests << " and " << all->cb.found
          << "/" << all->cb.tests << ", Fisher p " << pValue(all->pf) << " (Holm " << pValue(all->pf_adj) << ")"
          << (all->pf_adj < 0.05 ? " (a difference larger than chance)" : " (within chance)");
        if (all->timed)
          s << "; find times Mann-Whitney p " << pValue(all->pm) << " (Holm " << pValue(all->pm_adj) << ")"
            << (all->pm_adj < 0.05 ? " (a difference larger than chance)" : " (within chance)");
        s << ".\n";
      }
      s << "\n";
    }
  return s.str();
}

}  // namespace simswift::experiment
