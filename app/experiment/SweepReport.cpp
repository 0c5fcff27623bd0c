#include "app/experiment/SweepReport.hpp"

#include <sstream>

#include "app/experiment/Csv.hpp"
#include "common/random/DeriveSeed.hpp"

namespace simswift::experiment {

namespace {

std::string intervalText(const stats::Interval& i, int decimals, double scale = 1.0) {
  return "[" + fixed(i.lo * scale, decimals) + ", " + fixed(i.hi * scale, decimals) + "]";
}

}  // namespace

std::vector<CellRow> cellRows(const Experiment& e, const std::vector<TrialResult>& results) {
  using common::random::deriveSeed;
  const int per_cell = e.trialsPerCell();
  std::vector<CellRow> rows;
  for (int c = 0; c < e.numCells(); ++c)
    for (size_t s = 0; s < e.setups.size(); ++s) {
      CellRow r;
      r.cell = c;
      r.setup = static_cast<int>(s);
      r.first_trial = c * per_cell;
      r.last_trial = (c + 1) * per_cell - 1;
      for (const TrialResult& t : results) {
        if (t.trial < r.first_trial || t.trial > r.last_trial || t.setup != e.setups[s].name) continue;
        if (!t.failed.empty()) continue;  // its program failed: neither found nor not found
        ++r.tests;
        if (t.found) {
          ++r.found;
          r.times.push_back(t.seconds);
        }
      }
      r.rate = stats::wilson(r.found, r.tests);
      for (double t : r.times) r.mean_s += t / static_cast<double>(r.times.size());
      // Its own seed per row: every run prints the same interval.
      r.bootstrap_seed = deriveSeed(
          deriveSeed(deriveSeed(e.seed, common::random::seed_tag::kSweepBootstrap), static_cast<uint64_t>(c)),
          static_cast<uint64_t>(s));
      r.mean_ci = stats::bootstrapMean(r.times, r.bootstrap_seed);
      rows.push_back(std::move(r));
    }
  return rows;
}

std::string cellsCsv(const Experiment& e, const std::vector<CellRow>& rows) {
  std::ostringstream s;
  s << "cell";
  for (const SweepAxis& a : e.sweep) s << ',' << csvField(a.path);
  s << ",setup,first_trial,last_trial,tests,found,find_rate,find_rate_lo,find_rate_hi,mean_s,mean_s_lo,mean_s_hi,"
       "bootstrap_seed\n";
  for (const CellRow& r : rows) {
    s << r.cell;
    const std::vector<int> choice = sweepChoice(e.sweep, r.cell);
    for (size_t k = 0; k < e.sweep.size(); ++k) s << ',' << csvField(e.sweep[k].values[choice[k]].label);
    s << ',' << e.setups[r.setup].name << ',' << r.first_trial << ',' << r.last_trial << ',' << r.tests << ','
      << r.found << ',' << fixed(r.tests ? static_cast<double>(r.found) / r.tests : 0, 4) << ','
      << fixed(r.rate.lo, 4) << ',' << fixed(r.rate.hi, 4) << ',';
    if (r.times.empty()) s << ",,";
    else s << fixed(r.mean_s, 2) << ',' << fixed(r.mean_ci.lo, 2) << ',' << fixed(r.mean_ci.hi, 2);
    s << ',' << r.bootstrap_seed << '\n';
  }
  return s.str();
}

std::string sweepFigureName(const SweepAxis& axis) {
  std::string n = "sweep_" + axis.path;  // paths hold letters, digits, _, - and dots
  for (char& c : n)
    if (c == '.') c = '_';
  return n + ".png";
}

std::string sweepSection(const Experiment& e, const std::vector<CellRow>& rows) {
  std::ostringstream s;
  const int per_cell = e.trialsPerCell();
  s << "## Sweep\n\n" << e.numCells() << " cells: every combination of";
  for (size_t k = 0; k < e.sweep.size(); ++k) {
    s << (k == 0 ? " " : k + 1 == e.sweep.size() ? " and " : ", ") << "`" << e.sweep[k].path << "` (";
    for (size_t v = 0; v < e.sweep[k].values.size(); ++v) s << (v ? ", " : "") << e.sweep[k].values[v].label;
    s << ")";
  }
  s << ", each set into the experiment above. Each cell runs all " << per_cell
    << " trials (setups x ball positions x trials per position): cell c holds trials " << per_cell << "c to "
    << per_cell << "c + " << per_cell - 1 << " (results.csv names each trial's cell and values). Every cell draws "
    << "the same trial seeds, so cells differ by their settings, not by their draws";
  if (per_cell <= 30) {
    s << "; the seeds, in trial order within a cell:";
    for (int i = 0; i < per_cell; ++i) s << (i ? ", " : " ") << trialSpec(e, i).seed;
  } else {
    s << " (each trial's seed is in results.csv)";
  }
  s << ".\n\n"
    << "Per cell and setup, over all ball positions: find rate with its Wilson 95 % interval, mean find time over "
       "the finds with a percentile bootstrap 95 % interval (2000 resamples, seeded per row: cells.csv has the "
       "seeds). The report's other tables pool every cell.\n\n| Cell |";
  std::string rule = "|---:|";
  for (const SweepAxis& a : e.sweep) {
    s << " `" << a.path << "` |";
    rule += "---|";
  }
  s << " Setup | Found | Find rate (95 % CI) | Mean find s (95 % CI) |\n" << rule << "---|---:|---:|---:|\n";
  for (const CellRow& r : rows) {
    s << "| " << r.cell << " |";
    const std::vector<int> choice = sweepChoice(e.sweep, r.cell);
    for (size_t k = 0; k < e.sweep.size(); ++k) s << " " << e.sweep[k].values[choice[k]].label << " |";
    s << " `" << e.setups[r.setup].name << "` | " << r.found << "/" << r.tests << " | ";
    if (r.tests) s << fixed(100.0 * r.found / r.tests, 0) << " % " << intervalText(r.rate, 0, 100.0) << " %";
    else s << "-";
    s << " | ";
    if (r.times.empty()) s << "- |\n";
    else s << fixed(r.mean_s, 2) << " " << intervalText(r.mean_ci, 2) << " |\n";
  }
  s << "\nFigures (find rate and mean find time against each swept value, with the intervals above; one line per "
       "setup and combination of the other swept values):";
  for (const SweepAxis& a : e.sweep) s << " [" << a.path << "](figures/" << sweepFigureName(a) << ")";
  s << ".\n\n";
  return s.str();
}

}  // namespace simswift::experiment
