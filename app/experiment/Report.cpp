#include "app/experiment/Report.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "common/libagent/SharedNames.hpp"
#include "app/experiment/Statistics.hpp"
#include "app/experiment/SweepReport.hpp"
#include "app/experiment/ThesisTables.hpp"

namespace simswift::experiment {

PositionStats positionStats(int position, int tests, const std::vector<double>& found_times) {
  PositionStats p;
  p.position = position;
  p.tests = tests;
  p.found = static_cast<int>(found_times.size());
  p.not_found = tests - p.found;
  for (double t : found_times) p.total_s += t;
  p.avg_s = p.found ? p.total_s / p.found : 0;
  if (p.found >= 2) {
    double ss = 0;
    for (double t : found_times) ss += (t - p.avg_s) * (t - p.avg_s);
    p.sd_s = std::sqrt(ss / p.found);  // population
  }
  return p;
}

SummaryRow sumRows(const std::vector<PositionStats>& rows) {
  SummaryRow s;
  for (const PositionStats& p : rows) {
    s.tests += p.tests;
    s.found += p.found;
    s.not_found += p.not_found;
    s.total_s += p.total_s;
    s.avg_s += p.avg_s;
    s.sd_s += p.sd_s;
  }
  return s;
}

SummaryRow meanRows(const std::vector<PositionStats>& rows) {
  SummaryRow s = sumRows(rows);
  const double n = rows.empty() ? 1 : static_cast<double>(rows.size());
  s.tests /= n;
  s.found /= n;
  s.not_found /= n;
  s.total_s /= n;
  s.avg_s /= n;
  s.sd_s /= n;
  return s;
}

std::vector<PositionStats> setupTable(const Experiment& e, const std::vector<TrialResult>& results, int setup) {
  std::vector<PositionStats> rows;
  const std::string& name = e.setups[setup].name;
  for (const BallPosition& b : e.balls) {
    int tests = 0;
    std::vector<double> times;
    for (const TrialResult& r : results) {
      if (r.setup != name || r.position != b.number) continue;
      if (!r.failed.empty()) continue;  // its program failed: neither found nor not found
      ++tests;
      if (r.found) times.push_back(r.seconds);
    }
    rows.push_back(positionStats(b.number, tests, times));
  }
  return rows;
}

std::vector<std::pair<int, int>> summaryGroups(int rows) {
  std::vector<std::pair<int, int>> g;
  for (int i = 0; i < rows; i += 5) g.push_back({i, std::min(rows, i + 5)});
  return g;
}

namespace {

std::string f2(double v) { return fixed(v, 2); }

std::string countRow(const std::string& label, const SummaryRow& s) {
  return "| " + label + " | " + fixed(s.tests, 0) + " | " + fixed(s.found, 0) + " | " + fixed(s.not_found, 0) +
         " | | | |\n";
}
std::string meanRow(const std::string& label, const SummaryRow& s) {
  return "| " + label + " | " + f2(s.tests) + " | " + f2(s.found) + " | " + f2(s.not_found) + " | " + f2(s.total_s) +
         " | " + f2(s.avg_s) + " | " + f2(s.sd_s) + " |\n";
}

std::string positionsLabel(const std::vector<PositionStats>& rows, int a, int b) {
  return std::to_string(rows[a].position) + "-" + std::to_string(rows[b - 1].position);
}

// The thesis's table layout for one setup.
std::string thesisLayout(const std::vector<PositionStats>& rows) {
  std::ostringstream s;
  s << "| Position | Tests | Found | Not Found | Total Seconds | Avg. Seconds | Std. Dev. |\n"
    << "|---:|---:|---:|---:|---:|---:|---:|\n";
  const auto groups = summaryGroups(static_cast<int>(rows.size()));
  for (const auto& [a, b] : groups) {
    std::vector<PositionStats> part(rows.begin() + a, rows.begin() + b);
    for (const PositionStats& p : part)
      s << "| " << p.position << " | " << p.tests << " | " << p.found << " | " << p.not_found << " | "
        << f2(p.total_s) << " | " << f2(p.avg_s) << " | " << f2(p.sd_s) << " |\n";
    if (groups.size() > 1) {
      const std::string l = " (" + positionsLabel(rows, a, b) + ")";
      s << countRow("Sub-Total:" + l, sumRows(part)) << meanRow("Sub-Average:" + l, meanRows(part));
    }
  }
  const std::string prefix = groups.size() > 1 ? "Grand " : "";
  s << countRow(prefix + "Total:", sumRows(rows)) << meanRow(prefix + "Average:", meanRows(rows));
  return s.str();
}

std::string robotsLine(const Setup& s) {
  std::ostringstream o;
  for (size_t i = 0; i < s.robots.size(); ++i) {
    const ExperimentRobot& r = s.robots[i];
    o << (i ? "; " : "") << "t" << r.team << "p" << r.player << " " << r.behaviour << " at ("
      << fixed(r.x * 1000, 0) << ", " << fixed(r.y * 1000, 0) << ") mm";
  }
  return o.str();
}

// Ours beside one thesis table (5.3-5.8), position by position, over the
// positions both have; the summary row is over those positions only.
struct Beside {
  std::vector<int> positions;
  int thesis_found = 0, thesis_tests = 0, our_found = 0, our_tests = 0;
  double thesis_total_s = 0, our_total_s = 0;
};

Beside besideThesis(const ThesisTable& t, const std::vector<PositionStats>& ours) {
  Beside b;
  for (const PositionStats& p : ours)
    for (const ThesisRow& r : t.rows)
      if (r.position == p.position) {
        b.positions.push_back(p.position);
        b.thesis_found += r.found;
        b.thesis_tests += r.tests;
        b.thesis_total_s += r.total_s;
        b.our_found += p.found;
        b.our_tests += p.tests;
        b.our_total_s += p.total_s;
      }
  return b;
}

std::string rate(int found, int tests) {
  return std::to_string(found) + "/" + std::to_string(tests) + " (" +
         fixed(tests ? 100.0 * found / tests : 0, 0) + " %)";
}

std::string meanOverFinds(double total, int found) { return found ? f2(total / found) : "-"; }

std::string tableTitle(const ThesisTable& t) {
  return t.number + " (" + t.component + ", " + std::to_string(t.robots) + " robot" + (t.robots > 1 ? "s" : "") +
         ", " + (t.real ? "real NAO V5s" : "simulation") + ")";
}

std::string besideTable(const ThesisTable& t, const std::vector<PositionStats>& ours) {
  std::ostringstream s;
  s << "Beside thesis table " << tableTitle(t) << ":\n\n"
    << "| Position | Found (thesis) | Found (ours) | Avg. Seconds (thesis) | Avg. Seconds (ours) | Std. Dev. (thesis) "
       "| Std. Dev. (ours) |\n|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const PositionStats& p : ours) {
    const ThesisRow* r = nullptr;
    for (const ThesisRow& q : t.rows)
      if (q.position == p.position) r = &q;
    s << "| " << p.position << " | " << (r ? std::to_string(r->found) + "/" + std::to_string(r->tests) : "-") << " | "
      << p.found << "/" << p.tests << " | " << (r ? f2(r->avg_s) : "-") << " | " << f2(p.avg_s) << " | "
      << (r ? f2(r->sd_s) : "-") << " | " << f2(p.sd_s) << " |\n";
  }
  const Beside b = besideThesis(t, ours);
  s << "| Positions in both (" << b.positions.size() << ") | " << b.thesis_found << "/" << b.thesis_tests << " | "
    << b.our_found << "/" << b.our_tests << " | " << meanOverFinds(b.thesis_total_s, b.thesis_found) << " | "
    << meanOverFinds(b.our_total_s, b.our_found) << " | | |\n\n"
    << "The last row's seconds are means over the finds (Total / Found over those positions).\n\n";
  return s.str();
}


}  // namespace

const char* const kWallClockHeading = "## Wall clock (differs between runs)";

std::string deterministicPart(const std::string& report) {
  const size_t k = report.find(std::string("\n") + kWallClockHeading);
  return k == std::string::npos ? report : report.substr(0, k + 1);
}

std::string wallClockSection(const Experiment& e, const std::vector<TrialResult>& results, const RunWall* run) {
  std::ostringstream s;
  s << kWallClockHeading << "\n\n"
    << "Real-time factor = simulated s / wall s of one trial in its worker process, i.e. per core (a trial's robot "
       "threads take turns in lock-step), penalised start included. These figures depend on the machine and its "
       "load; nothing above this section does. Per trial: timing.md, timing.csv.\n\n"
    << "| Setup | Trials | Simulated s | Worker wall s | Real-time factor: min | median | max |\n"
    << "|---|---:|---:|---:|---:|---:|---:|\n";
  auto row = [&](const std::string& label, const std::string& setup) {
    double sim = 0, wall = 0;
    std::vector<double> rtf;
    for (const TrialResult& r : results) {
      if ((!setup.empty() && r.setup != setup) || r.wall_s <= 0) continue;
      sim += r.sim_s;
      wall += r.wall_s;
      rtf.push_back(r.realTimeFactor());
    }
    if (rtf.empty()) {
      s << "| " << label << " | 0 | | | | | |\n";
      return;
    }
    s << "| " << label << " | " << rtf.size() << " | " << fixed(sim, 1) << " | " << fixed(wall, 1) << " | "
      << f2(*std::min_element(rtf.begin(), rtf.end())) << " | " << f2(stats::median(rtf)) << " | "
      << f2(*std::max_element(rtf.begin(), rtf.end())) << " |\n";
  };
  for (const Setup& st : e.setups) row("`" + st.name + "`", st.name);
  if (e.setups.size() > 1) row("all", "");
  s << "\n";
  // Peak resident memory, as each trial's process recorded it (timing.csv).
  double peak = 0;
  int recorded = 0;
  for (const TrialResult& r : results)
    if (r.peak_mb > 0) {
      peak = std::max(peak, r.peak_mb);
      ++recorded;
    }
  if (recorded > 0)
    s << "Peak resident memory of one trial process: " << fixed(peak, 0) << " MB (the largest of " << recorded
      << " trials; per trial in timing.csv).\n\n";
  if (run && run->ran > 0) {
    const long w = std::lround(run->wall_s);
    s << "The run that completed this folder ran " << run->ran << " trial(s) with " << run->jobs
      << " worker process(es) in " << w / 60 << " min " << w % 60 << " s of wall time ("
      << fixed(run->wall_s, 1) << " s): " << fixed(run->trial_sim_s, 1) << " simulated s, "
      << fixed(run->wall_s > 0 ? run->trial_sim_s / run->wall_s : 0, 2) << " simulated s per wall s on the whole "
      << "machine.";
    // Trials of folders written before timing.csv had peak_mb: the run's.
    if (recorded == 0) s << " Peak resident memory of one trial process: " << fixed(run->peak_trial_mb, 0) << " MB.";
    s << "\n";
  } else {
    s << "This folder was assembled from earlier runs or merged shards: no single run's wall time.\n";
  }
  return s.str();
}

namespace {

void introSection(std::ostream& s, const Experiment& e) {
  s << "# Find-ball experiment `" << e.name << "`\n\n"
    << e.numTrials() << " trials: " << (e.swept() ? std::to_string(e.numCells()) + " sweep cells x " : "")
    << e.setups.size() << " setup(s) x " << e.balls.size() << " ball position(s) x "
    << e.trials_per_position << " trial(s). Time limit " << fixed(e.time_limit, 1) << " s; found = a robot within "
    << fixed(e.found.distance * 1000, 0) << " mm of the ball (inclusive)"
    << (e.found.sees ? " whose vision (the detector model its perception gets) reports the ball in the latest "
                       "frame, at that detected distance"
                     : "")
    << "; a robot down for "
    << fixed(e.fallen.sideline_after, 1) << " s is moved to the sideline. Seed " << e.seed
    << " (each trial's seed is in results.csv).\n\n"
    << "Seconds are simulated seconds. Avg. Seconds = Total / Found (0 when none found); Std. Dev. is the "
       "population standard deviation of the find times; the Average rows are the plain means of the "
       "position rows, as in the thesis. Trials start as the thesis's experiment controller started them: "
       "the robots stand penalised at their start poses for "
    << fixed(e.start.penalised, 2)
    << " s, then the game goes to PLAYING and they are unpenalised; find times count from that moment. "
       "Wall-clock figures (real-time factor) are in the last section and in timing.md: everything above that "
       "section is the same in every run.\n\n";
}

void failedSection(std::ostream& s, const std::vector<TrialResult>& results) {
  int failed = 0;
  for (const TrialResult& r : results) failed += !r.failed.empty();
  if (!failed) return;
  s << "**" << failed << " trial(s) failed** (a launched robot program crashed, exited or never attached); "
    << "they are left out of every table below (Tests counts the trials that ran). Their logs are in "
    << "trials/<trial>/:\n\n";
  for (const TrialResult& r : results)
    if (!r.failed.empty()) s << "- trial " << r.trial << " (" << r.setup << ", position " << r.position << "): "
                              << r.failed << "\n";
  s << "\n";
}

void ballPositionsLine(std::ostream& s, const Experiment& e) {
  s << "Ball positions (table 5.2):";
  for (const BallPosition& b : e.balls)
    s << " " << b.number << " (" << fixed(b.x * 1000, 0) << ", " << fixed(b.y * 1000, 0) << ")";
  s << " mm.\n\n";
}

// Thesis table -> the index of the setup that repeats it (the last one naming it).
std::map<std::string, int> setupsOfTables(const Experiment& e) {
  std::map<std::string, int> setup_of_table;
  for (size_t si = 0; si < e.setups.size(); ++si)
    if (!e.setups[si].thesis_table.empty()) setup_of_table[e.setups[si].thesis_table] = static_cast<int>(si);
  return setup_of_table;
}

// Beyond the thesis's table: a mean over finds, falls, moves, walking.
void setupRobotsTable(std::ostream& s, const Setup& setup, const std::vector<TrialResult>& results) {
  std::vector<double> times;
  int tests = 0, resets = 0;
  std::vector<double> dist(setup.robots.size(), 0);
  std::vector<int> falls(setup.robots.size(), 0), contact_falls(setup.robots.size(), 0),
      moves(setup.robots.size(), 0), finds(setup.robots.size(), 0);
  for (const TrialResult& r : results) {
    if (r.setup != setup.name) continue;
    ++tests;
    resets += r.resets;
    if (r.found) times.push_back(r.seconds);
    for (size_t k = 0; k < r.robots.size() && k < setup.robots.size(); ++k) {
      dist[k] += r.robots[k].distance_m;
      falls[k] += r.robots[k].falls;
      contact_falls[k] += r.robots[k].contact_falls;
      moves[k] += r.robots[k].sideline_moves;
      if (r.found && r.finder == common::libagent::robotTag(r.robots[k].team, r.robots[k].player))
        ++finds[k];
    }
  }
  const PositionStats all = positionStats(0, tests, times);
  s << "Find rate " << all.found << "/" << all.tests << " ("
    << fixed(all.tests ? 100.0 * all.found / all.tests : 0, 1) << " %); over the " << all.found
    << " finds: mean " << f2(all.avg_s) << " s, standard deviation " << f2(all.sd_s) << " s. World resets: "
    << resets << ".\n\n"
    << "| Robot | Finds | Mean walked (m/trial) | Falls | of which after robot contact | Sideline moves |\n"
    << "|---|---:|---:|---:|---:|---:|\n";
  for (size_t k = 0; k < setup.robots.size(); ++k)
    s << "| t" << setup.robots[k].team << "p" << setup.robots[k].player << " | " << finds[k] << " | "
      << fixed(tests ? dist[k] / tests : 0, 2) << " | " << falls[k] << " | " << contact_falls[k] << " | " << moves[k]
      << " |\n";
}

void setupSection(std::ostream& s, const Experiment& e, const std::vector<TrialResult>& results, int si) {
  const Setup& setup = e.setups[si];
  const std::vector<PositionStats> rows = setupTable(e, results, si);
  s << "## Setup `" << setup.name << "`";
  if (!setup.thesis_table.empty()) s << " (repeats thesis table " << setup.thesis_table << ")";
  s << "\n\n" << setup.robots.size() << " robot(s): " << robotsLine(setup) << ".\n\n" << thesisLayout(rows) << "\n";
  if (const ThesisTable* t = thesisTable(setup.thesis_table)) s << besideTable(*t, rows);
  setupRobotsTable(s, setup, results);
  s << "\nFigures: [routes](figures/routes_" << setup.name << ".png) (as the thesis's figures 5.2 and 5.3), "
    << "[find times](figures/findtime_" << setup.name << ".png) (box plot per position).\n\n";
}

// Per component (setup) beside its thesis table: find rate and mean find
// time over the positions both have.
void componentsSection(std::ostream& s, const Experiment& e, const std::vector<TrialResult>& results) {
  s << "## Per component beside the thesis\n\n"
    << "Each setup that names a thesis table, over the ball positions both have; mean find time = Total "
       "Seconds / Found over those positions (the thesis's printed Average rows are the plain means of its "
       "position averages, counting 0.00 for a position never found).\n\n"
    << "| Setup | Thesis table | Positions | Find rate (thesis) | Find rate (ours) | Mean find s (thesis) | Mean "
       "find s (ours) |\n|---|---|---:|---:|---:|---:|---:|\n";
  for (size_t si = 0; si < e.setups.size(); ++si) {
    const ThesisTable* t = thesisTable(e.setups[si].thesis_table);
    if (!t) continue;
    const Beside b = besideThesis(*t, setupTable(e, results, static_cast<int>(si)));
    s << "| `" << e.setups[si].name << "` | " << tableTitle(*t) << " | " << b.positions.size() << " | "
      << rate(b.thesis_found, b.thesis_tests) << " | " << rate(b.our_found, b.our_tests) << " | "
      << meanOverFinds(b.thesis_total_s, b.thesis_found) << " | " << meanOverFinds(b.our_total_s, b.our_found)
      << " |\n";
  }
  s << "\n";
}

void comparisonsHeader(std::ostream& s, const Experiment& e) {
  s << "## Beside the thesis (tables 5.9-5.12)\n\n"
    << "Thesis columns are the thesis's own figures (sim = its rcssserver3d simulation, real = NAO V5s); "
       "ours are this run's setups that name the table in `thesis_table:`. Found counts are shown as "
       "found/tests. Each column's Total/Average row is over its own positions (the thesis's: all of its "
       "table); the per-component table above compares the positions both have.\n\n";
  // Positions are compared by number: say so where ours lie elsewhere.
  std::string moved;
  for (const BallPosition& b : e.balls)
    for (const ThesisPoint& p : thesisBallPositions())
      if (p.number == b.number && (std::abs(p.x_mm - b.x * 1000) > 1 || std::abs(p.y_mm - b.y * 1000) > 1))
        moved += (moved.empty() ? "" : ", ") + std::to_string(b.number);
  if (!moved.empty())
    s << "**Note:** ball position(s) " << moved
      << " of this experiment are not where table 5.2 puts them; those rows compare different places.\n\n";
}

// One comparison's thesis columns and ours: the table of setup_of_table's
// setup per thesis table that has one (empty rows where none).
struct ComparisonColumns {
  const ThesisComparison& c;
  const std::map<std::string, int>& setup_of_table;
  std::vector<std::vector<PositionStats>> ours;
  bool hasOurs(size_t k) const { return setup_of_table.count(c.tables[k]) > 0; }
};

void comparisonHeading(std::ostream& s, const Experiment& e, const std::vector<TrialResult>& results,
                       ComparisonColumns& cols) {
  const ThesisComparison& c = cols.c;
  s << "### Table " << c.number << ": " << c.title << "\n\n| |";
  std::string rule = "|---|";
  for (size_t k = 0; k < c.tables.size(); ++k) {
    const ThesisTable* t = thesisTable(c.tables[k]);
    s << " thesis " << t->number << " (" << t->component << ", " << t->robots << " robot"
      << (t->robots > 1 ? "s" : "") << ", " << (t->real ? "real" : "sim") << ") |";
    rule += "---:|";
    auto it = cols.setup_of_table.find(c.tables[k]);
    if (it != cols.setup_of_table.end()) {
      s << " ours: `" << e.setups[it->second].name << "` |";
      rule += "---:|";
      cols.ours[k] = setupTable(e, results, it->second);
    }
  }
  s << "\n" << rule << "\n";
}

void comparisonPositionRow(std::ostream& s, const ComparisonColumns& cols, int pos) {
  const ThesisComparison& c = cols.c;
  s << "| Ball Pos " << pos << (c.what == ThesisComparison::What::Found ? "" : " Avg. Time") << " |";
  for (size_t k = 0; k < c.tables.size(); ++k) {
    const ThesisTable* t = thesisTable(c.tables[k]);
    if (pos >= 1 && pos <= static_cast<int>(c.values.size())) {
      const double v = c.values[pos - 1][k];
      s << " " << (c.what == ThesisComparison::What::Found ? fixed(v, 0) + "/" + std::to_string(t->rows[pos - 1].tests)
                                                         : f2(v))
        << " |";
    } else {
      s << " - |";
    }
    if (cols.hasOurs(k)) {
      const PositionStats* p = nullptr;
      for (const PositionStats& q : cols.ours[k])
        if (q.position == pos) p = &q;
      if (!p) s << " - |";
      else if (c.what == ThesisComparison::What::Found) s << " " << p->found << "/" << p->tests << " |";
      else s << " " << f2(p->avg_s) << " |";
    }
  }
  s << "\n";
}

void comparisonBottomRow(std::ostream& s, const ComparisonColumns& cols) {
  const ThesisComparison& c = cols.c;
  s << "| " << (c.what == ThesisComparison::What::Found ? "Total:" : "Average:") << " |";
  for (size_t k = 0; k < c.tables.size(); ++k) {
    const ThesisTable* t = thesisTable(c.tables[k]);
    int tests = 0;
    for (const ThesisRow& r : t->rows) tests += r.tests;
    s << " " << (c.what == ThesisComparison::What::Found ? fixed(c.bottom[k], 0) + "/" + std::to_string(tests)
                                                       : f2(c.bottom[k]))
      << " |";
    if (cols.hasOurs(k)) {
      const SummaryRow sum = sumRows(cols.ours[k]), mean = meanRows(cols.ours[k]);
      if (c.what == ThesisComparison::What::Found) s << " " << fixed(sum.found, 0) << "/" << fixed(sum.tests, 0) << " |";
      else s << " " << f2(mean.avg_s) << " |";
    }
  }
  s << "\n\n";
}

void comparisonTable(std::ostream& s, const Experiment& e, const std::vector<TrialResult>& results,
                     const ThesisComparison& c, const std::map<std::string, int>& setup_of_table) {
  ComparisonColumns cols{c, setup_of_table, std::vector<std::vector<PositionStats>>(c.tables.size())};
  comparisonHeading(s, e, results, cols);
  std::set<int> positions;
  for (size_t p = 0; p < c.values.size(); ++p) positions.insert(static_cast<int>(p) + 1);
  for (const auto& rows : cols.ours)
    for (const PositionStats& p : rows) positions.insert(p.position);
  for (int pos : positions) comparisonPositionRow(s, cols, pos);
  comparisonBottomRow(s, cols);
}

// Comparisons 5.9-5.12: thesis columns beside ours.
void comparisonsSection(std::ostream& s, const Experiment& e, const std::vector<TrialResult>& results,
                        const std::map<std::string, int>& setup_of_table) {
  bool header = false;
  for (const ThesisComparison& c : thesisComparisons()) {
    bool any = false;
    for (const std::string& t : c.tables) any = any || setup_of_table.count(t);
    if (!any) continue;
    if (!header) {
      comparisonsHeader(s, e);
      header = true;
    }
    comparisonTable(s, e, results, c, setup_of_table);
  }
}

}  // namespace

std::string reportMarkdown(const Experiment& e, const std::vector<TrialResult>& results) {
  std::ostringstream s;
  introSection(s, e);
  failedSection(s, results);
  if (e.swept()) s << sweepSection(e, cellRows(e, results));
  ballPositionsLine(s, e);
  for (size_t si = 0; si < e.setups.size(); ++si) setupSection(s, e, results, static_cast<int>(si));
  const std::map<std::string, int> setup_of_table = setupsOfTables(e);
  if (!setup_of_table.empty()) componentsSection(s, e, results);
  comparisonsSection(s, e, results, setup_of_table);
  s << statisticsSection(e, results);
  return s.str();
}

}  // namespace simswift::experiment
