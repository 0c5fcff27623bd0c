#include "app/experiment/Trial.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "agent/libagent/SharedNames.hpp"
#include "sim/programs/Programs.hpp"

namespace simswift::experiment {

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

}  // namespace simswift::experiment
