#include "app/experiment/TimingPage.hpp"

#include <algorithm>
#include <sstream>

#include "app/experiment/Statistics.hpp"

namespace simswift::experiment {

std::string timingMarkdown(const Experiment& e, const std::vector<TrialResult>& results, const RunWall* run) {
  std::ostringstream s;
  double sim = 0, wall = 0;  // s, summed over the trials
  std::vector<double> rtf, peak;
  for (const TrialResult& r : results) {
    sim += r.sim_s;
    wall += r.wall_s;
    if (r.wall_s > 0) rtf.push_back(r.realTimeFactor());
    if (r.peak_mb > 0) peak.push_back(r.peak_mb);
  }
  std::sort(rtf.begin(), rtf.end());
  std::sort(peak.begin(), peak.end());
  s << "# Wall clock of `" << e.name << "`\n\n"
    << "Real-time factor = simulated s / wall s of one trial in one worker process (per core). "
    << "These figures depend on the machine and its load; nothing else in the folder does (but report.md's "
    << "last section, which summarises them).\n\n";
  if (run && run->ran > 0)
    s << "The run that completed this folder: " << run->ran << " trial(s), " << run->jobs << " worker process(es), "
      << fixed(run->wall_s, 1) << " s of wall time.\n\n";
  if (!rtf.empty())
    s << "Trials " << results.size() << "; simulated " << fixed(sim, 1) << " s in " << fixed(wall, 1)
      << " s of worker time; real-time factor min " << fixed(rtf.front(), 2) << ", median "
      << fixed(stats::median(rtf), 2) << ", max " << fixed(rtf.back(), 2) << ".\n\n";
  if (!peak.empty())
    s << "Peak resident memory of one trial process (MB): min " << fixed(peak.front(), 0) << ", median "
      << fixed(stats::median(peak), 0) << ", max " << fixed(peak.back(), 0) << ".\n\n";
  s << "| Trial | Setup | Position | Simulated s | Wall s | Real-time factor | Peak MB |\n"
       "|---:|---|---:|---:|---:|---:|---:|\n";
  for (const TrialResult& r : results)
    s << "| " << r.trial << " | " << r.setup << " | " << r.position << " | " << fixed(r.sim_s, 2) << " | "
      << fixed(r.wall_s, 2) << " | " << fixed(r.realTimeFactor(), 2) << " | "
      << (r.peak_mb > 0 ? fixed(r.peak_mb, 0) : std::string()) << " |\n";
  return s.str();
}

}  // namespace simswift::experiment
