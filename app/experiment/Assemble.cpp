// assemble() (Batch.hpp): the results folder's combined files from its
// trial files, in trial order, so the folder is the same however its
// trials were run (jobs, shards, resumes).
#include <string>
#include <vector>

#include "app/experiment/Batch.hpp"
#include "app/experiment/Files.hpp"
#include "app/experiment/FolderFigures.hpp"
#include "app/experiment/ResultsFolder.hpp"
#include "app/experiment/SweepReport.hpp"
#include "app/experiment/TimingPage.hpp"

namespace simswift::experiment {

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
  writeAtomic(dir + "/timing.md", timingMarkdown(e, results, run));
  writeSetupFigures(e, dir, results, tracks, notes);
  if (e.swept()) {
    // One row per cell and setup (cells.csv), one figure per swept path.
    const std::vector<CellRow> rows = cellRows(e, results);
    writeAtomic(dir + "/cells.csv", cellsCsv(e, rows));
    writeSweepFigures(e, dir, rows, notes);
  }
}

}  // namespace simswift::experiment
