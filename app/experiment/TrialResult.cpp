#include "app/experiment/TrialResult.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "common/libagent/SharedNames.hpp"
#include "app/experiment/Csv.hpp"

namespace simswift::experiment {

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string csvHeader(int robots, const std::vector<SweepAxis>& sweep) {
  std::string h = "trial";
  if (!sweep.empty()) h += ",cell";
  for (const SweepAxis& a : sweep) h += "," + csvField(a.path);
  h += ",setup,position,repeat,seed,found,seconds,finder,resets,failed";
  for (int k = 1; k <= robots; ++k) {
    const std::string r = "robot" + std::to_string(k) + "_";
    h += "," + r + "player," + r + "distance_m," + r + "falls," + r + "contact_falls," + r + "sideline_moves";
  }
  return h + "\n";
}

std::string csvRow(const TrialResult& r, int robots) {
  std::ostringstream s;
  s << r.trial << ',';
  if (r.cell >= 0) {
    s << r.cell << ',';
    for (const std::string& v : r.cell_values) s << csvField(v) << ',';
  }
  s << r.setup << ',' << r.position << ',' << r.repeat << ',' << r.seed << ','
    << (r.found ? 1 : 0) << ',' << (r.found ? fixed(r.seconds, 2) : "") << ',' << r.finder << ',' << r.resets << ','
    << r.failed;
  for (int k = 0; k < robots; ++k) {
    if (k < static_cast<int>(r.robots.size())) {
      const RobotOutcome& o = r.robots[k];
      s << ',' << common::libagent::robotTag(o.team, o.player) << ',' << fixed(o.distance_m, 3) << ',' << o.falls << ','
        << o.contact_falls << ',' << o.sideline_moves;
    } else {
      s << ",,,,,";
    }
  }
  s << '\n';
  return s.str();
}

TrialResult parseCsvRow(const std::string& line, int swept_paths) {
  std::vector<std::string> f = splitCsv(line);
  TrialResult r;
  if (swept_paths > 0) {
    // trial, cell, the cell's values, then the unswept row's fields.
    if (f.size() < static_cast<size_t>(swept_paths) + 2)
      throw std::runtime_error("bad results row (" + std::to_string(f.size()) + " fields): " + line);
    try {
      r.cell = std::stoi(f[1]);
    } catch (const std::exception& ex) {
      throw std::runtime_error(std::string("bad results row: cell: ") + ex.what() + ": " + line);
    }
    r.cell_values.assign(f.begin() + 2, f.begin() + 2 + swept_paths);
    f.erase(f.begin() + 1, f.begin() + 2 + swept_paths);
  }
  if (f.size() < 10 || (f.size() - 10) % 5 != 0)
    throw std::runtime_error("bad results row (" + std::to_string(f.size()) + " fields): " + line);
  try {
    r.trial = std::stoi(f[0]);
    r.setup = f[1];
    r.position = std::stoi(f[2]);
    r.repeat = std::stoi(f[3]);
    r.seed = std::stoull(f[4]);
    r.found = f[5] == "1";
    r.seconds = r.found ? std::stod(f[6]) : 0;
    r.finder = f[7];
    r.resets = std::stoi(f[8]);
    r.failed = f[9];
    for (size_t k = 10; k + 4 < f.size(); k += 5) {
      if (f[k].empty()) continue;
      RobotOutcome o;
      if (!common::libagent::parseRobotTag(f[k], &o.team, &o.player)) throw std::runtime_error("player " + f[k]);
      o.distance_m = std::stod(f[k + 1]);
      o.falls = std::stoi(f[k + 2]);
      o.contact_falls = std::stoi(f[k + 3]);
      o.sideline_moves = std::stoi(f[k + 4]);
      r.robots.push_back(o);
    }
  } catch (const std::exception& ex) {
    throw std::runtime_error(std::string("bad results row: ") + ex.what() + ": " + line);
  }
  return r;
}

std::string tracksHeader() { return "trial,setup,player,t,x,y,theta\n"; }

std::string tracksRows(const TrialResult& r, const Experiment& e) {
  std::ostringstream s;
  for (const TrackSample& p : r.tracks) {
    const RobotOutcome& o = r.robots[p.robot];
    s << r.trial << ',' << r.setup << ',' << common::libagent::robotTag(o.team, o.player) << ',' << fixed(p.t, 2) << ',' << fixed(p.x, 3)
      << ',' << fixed(p.y, 3) << ',' << fixed(p.theta, 3) << '\n';
  }
  return s.str();
}

std::string timingHeader() { return "trial,sim_s,wall_s,real_time_factor,peak_mb\n"; }

std::string timingRow(const TrialResult& r) {
  return std::to_string(r.trial) + "," + fixed(r.sim_s, 2) + "," + fixed(r.wall_s, 3) + "," +
         fixed(r.realTimeFactor(), 2) + "," + fixed(r.peak_mb, 1) + "\n";
}

void parseTimingRow(const std::string& row, TrialResult& r) {
  double sim = 0, wall = 0, rtf = 0, peak = 0;
  const int n = std::sscanf(row.c_str(), "%*d,%lf,%lf,%lf,%lf", &sim, &wall, &rtf, &peak);
  if (n >= 2) {
    r.sim_s = sim;
    r.wall_s = wall;
  }
  r.peak_mb = n >= 4 ? peak : 0;
}

}  // namespace simswift::experiment
