#include "app/experiment/Trial.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "agent/libagent/SharedNames.hpp"
#include "app/experiment/Csv.hpp"
#include "sim/programs/Programs.hpp"

namespace simswift::experiment {

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

namespace {


// Torso pose (field frame): x, y m, heading rad.
struct Pose2 {
  double x, y, theta, z;
};
Pose2 torsoPose(const World& w, int i) {
  const RobotBody::TorsoPose t = w.robot(i).torsoPose();
  return {t.x, t.y, t.heading, t.z};
}

// Where a robot down too long goes: its nearest touch line at its x (kept
// inside the field), facing the field; stepped toward the centre line while
// another robot stands within 0.4 m.
void sidelineSpot(const Experiment& e, const World& w, int i, double* x, double* y, double* theta) {
  const Pose2 p = torsoPose(w, i);
  const double half_l = e.field.length / 2 - 0.3;
  const double side = p.y >= 0 ? 1.0 : -1.0;
  *y = side * e.field.width / 2;
  *theta = -side * M_PI / 2;
  *x = std::max(-half_l, std::min(half_l, p.x));
  const double step = *x > 0 ? -0.4 : 0.4;
  for (int tries = 0; tries < 40; ++tries) {
    bool clear = true;
    for (int j = 0; j < w.numRobots(); ++j) {
      if (j == i) continue;
      const Pose2 o = torsoPose(w, j);
      if (std::hypot(o.x - *x, o.y - *y) < 0.4) clear = false;
    }
    if (clear) return;
    *x += step;
  }
}


}  // namespace

namespace {
std::unique_ptr<runner::Runner> startRunner(const Experiment& e, const TrialSpec& t, const runner::Scenario& sc,
                                            const TrialHooks& hooks);
void playTrial(const Experiment& e, const TrialSpec& t, const runner::Scenario& sc, const TrialHooks& hooks,
               TrialResult& res);

// What a trial's row says before it runs: which trial, and its robots with
// nothing walked, fallen or moved yet.
TrialResult trialHeader(const Experiment& e, const TrialSpec& t) {
  const Setup& setup = e.setups[t.setup];
  TrialResult res;
  res.trial = t.index;
  if (e.swept()) {
    res.cell = t.cell;
    const std::vector<int> choice = sweepChoice(e.sweep, t.cell);
    for (size_t k = 0; k < e.sweep.size(); ++k) res.cell_values.push_back(e.sweep[k].values[choice[k]].label);
  }
  res.setup = setup.name;
  res.position = e.balls[t.ball].number;
  res.repeat = t.repeat;
  res.seed = t.seed;
  for (const ExperimentRobot& r : setup.robots) res.robots.push_back(RobotOutcome{r.team, r.player});
  return res;
}
}  // namespace

std::unique_ptr<runner::Runner> startTrial(const Experiment& e, int index, const TrialHooks& hooks) {
  const TrialSpec t = trialSpec(e, index);
  const Experiment& cell = e.cell(t.cell);
  runner::Scenario sc = trialScenario(e, t);
  hooks.behaviours->configure(cell, t, sc);
  return startRunner(cell, t, sc, hooks);
}

TrialResult runTrial(const Experiment& e, int index, const TrialHooks& hooks, const std::string& program_logs) {
  using Clock = std::chrono::steady_clock;
  const auto wall0 = Clock::now();  // timing only
  const TrialSpec t = trialSpec(e, index);
  const Experiment& cell = e.cell(t.cell);  // the base with the cell's swept values
  runner::Scenario sc = trialScenario(e, t);
  hooks.behaviours->configure(cell, t, sc);

  TrialResult res = trialHeader(e, t);
  if (!program_logs.empty()) sc.program_logs = program_logs;
  try {
    playTrial(cell, t, sc, hooks, res);
  } catch (const runner::ProgramError& err) {
    // The trial failed, the batch goes on: the brief reason (no pid, no
    // path: results stay a function of the file), without the separators.
    std::string why = err.brief;
    for (char& c : why)
      if (c == ',' || c == '"') c = ';';
    res = trialHeader(e, t);  // nothing of the partial run is kept
    res.failed = why;
    std::fprintf(stderr, "trial %d failed: %s\n", index, err.what());
  }
  res.wall_s = std::chrono::duration<double>(Clock::now() - wall0).count();
  return res;
}

namespace {

// The trial's runner, started, its robots on their start poses (penalised).
std::unique_ptr<runner::Runner> startRunner(const Experiment& e, const TrialSpec& t, const runner::Scenario& sc,
                                            const TrialHooks& hooks) {
  const Setup& setup = e.setups[t.setup];
  auto run = std::make_unique<runner::Runner>(sc);
  // The robot programs' steps on this thread: no hand-over between threads
  // (the same results as named threads; two trials per two cores keep both busy).
  run->programs().setThreading(agent::program::Threading::Inline);
  hooks.behaviours->attach(e, t, *run);
  run->start();  // the t = 0 penalties: the GameController's placer takes the robots to the sideline
  // ... and the experiment puts them on their start poses, penalised, as
  // findballexp did (they stay there when unpenalised: Return::Sideline).
  for (size_t i = 0; i < setup.robots.size(); ++i)
    run->placeRobot(static_cast<int>(i), setup.robots[i].x, setup.robots[i].y, setup.robots[i].theta);
  hooks.behaviours->startPlay(e, t, *run);
  return run;
}

void playTrial(const Experiment& e, const TrialSpec& t, const runner::Scenario& sc, const TrialHooks& hooks,
               TrialResult& res) {
  const Setup& setup = e.setups[t.setup];
  const int n = static_cast<int>(setup.robots.size());
  const std::unique_ptr<runner::Runner> owned = startRunner(e, t, sc, hooks);
  runner::Runner& run = *owned;
  World& w = run.world();

  // In the robots' ticks (10 ms on a V5, 12 ms on a V6).
  const int64_t play = playTick(e, w.tickUs());  // PLAYING from the end of this tick: the trial's clock starts
  const int64_t limit = play + w.ticksIn(e.time_limit);
  const int64_t track_every = std::max<int64_t>(1, w.ticksIn(e.track_every));
  const int64_t sideline_ticks = std::max<int64_t>(1, w.ticksIn(e.fallen.sideline_after));
  auto clock = [&](int64_t tick) { return static_cast<double>(tick - play) * w.tickSeconds(); };  // s since PLAYING
  std::vector<int64_t> down_since(n, -1);  // tick the robot went down, -1 = up
  std::vector<runner::FallDetector> down(n);
  std::vector<Pose2> last(n);
  auto sample = [&](int i, bool count) {
    const Pose2 p = torsoPose(w, i);
    if (count) res.robots[i].distance_m += std::hypot(p.x - last[i].x, p.y - last[i].y);
    last[i] = p;
    res.tracks.push_back({i, clock(run.ticks()), p.x, p.y, p.theta});
  };

  while (run.ticks() < limit) {
    run.tick();  // 1.
    const int64_t tick = run.ticks();
    for (int i = 0; i < n; ++i) {  // 2.
      // Down and up by the runner's one fall detector (same thresholds as its
      // fall count); falls themselves are counted by the runner.
      down[i].update(torsoPose(w, i).z);
      if (!down[i].fallen) {
        down_since[i] = -1;
      } else if (down_since[i] < 0) {
        down_since[i] = tick;
      } else if (tick - down_since[i] >= sideline_ticks) {
        double x, y, theta;
        sidelineSpot(e, w, i, &x, &y, &theta);
        if (tick > play) sample(i, true);  // the walk up to the move counts, the move does not
        run.placeRobot(i, x, y, theta);
        if (tick > play) sample(i, false);  // where it was put (the track jumps here)
        else last[i] = torsoPose(w, i);
        ++res.robots[i].sideline_moves;
        down_since[i] = -1;
      }
    }
    if (tick < play) continue;  // penalised: nothing is timed or tracked yet
    if (tick == play) {  // the robots are unpenalised at the end of this tick: tracks start here
      for (int i = 0; i < n; ++i) sample(i, false);
      continue;
    }
    const int finder = hooks.found->finder(e, run);  // 4. (3. below, so the last leg is sampled)
    if ((tick - play) % track_every == 0 || finder >= 0 || tick == limit)
      for (int i = 0; i < n; ++i) sample(i, true);  // 3.
    if (finder >= 0) {
      res.found = true;
      res.seconds = clock(tick);
      res.finder = agent::libagent::robotTag(setup.robots[finder].team, setup.robots[finder].player);
      break;
    }
  }
  const runner::RunStats stats = run.stats();
  run.shutdown();
  res.resets = stats.blowups;
  for (int i = 0; i < n && i < static_cast<int>(stats.robots.size()); ++i) {
    res.robots[i].falls = stats.robots[i].falls;
    res.robots[i].contact_falls = stats.robots[i].contact_falls;
  }
  res.sim_s = stats.sim_s;
}

}  // namespace

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
      s << ',' << agent::libagent::robotTag(o.team, o.player) << ',' << fixed(o.distance_m, 3) << ',' << o.falls << ','
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
      if (!agent::libagent::parseRobotTag(f[k], &o.team, &o.player)) throw std::runtime_error("player " + f[k]);
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
    s << r.trial << ',' << r.setup << ',' << agent::libagent::robotTag(o.team, o.player) << ',' << fixed(p.t, 2) << ',' << fixed(p.x, 3)
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
