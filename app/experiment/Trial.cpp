#include "app/experiment/Trial.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cmath>
#include <cstdio>

#include "common/libagent/SharedNames.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/record/Recorder.hpp"

namespace simswift::experiment {

namespace {

// Torso pose (field frame): x, y, z m, heading rad.
struct Pose2 {
  double x, y, theta, z;
};
Pose2 torsoPose(const World& w, int i) {
  const RobotBody::TorsoPose t = w.robot(i).torsoPose();
  return {t.x, t.y, t.heading, t.z};
}

// The trial's clock, in the robots' ticks (10 ms on a V5, 12 ms on a V6).
struct TrialClock {
  int64_t play = 0;            // PLAYING from the end of this tick: the trial's clock starts
  int64_t limit = 0;           // the time limit's tick: the trial ends after it
  int64_t track_every = 1;     // ticks between track samples
  int64_t sideline_ticks = 1;  // ticks a robot stays down before its move to the sideline
  double tick_s = 0;           // s per tick
  double since(int64_t tick) const { return static_cast<double>(tick - play) * tick_s; }  // s since PLAYING
};

// Per robot, what the fallen rule and the tracks remember between ticks.
struct RobotWatch {
  runner::FallDetector down;  // down and up by the runner's one fall detector
  int64_t down_since = -1;    // tick the robot went down, -1 = up
  Pose2 last{};               // at the last track sample
};

// One trial as it passes through the stages of runTrial (Trial.hpp): each
// stage's comment says what of it the stage reads and writes.
struct TrialState {
  TrialSpec spec;                     // which trial: setup, ball, repeat, seed, cell
  const Experiment* cell = nullptr;   // the experiment with the trial's cell's swept values
  runner::Scenario scenario;          // the trial's world, robots, game, behaviours
  TrialResult result;                 // the results row, filled in stage by stage
  std::unique_ptr<runner::Runner> runner;
  TrialClock clock;
  std::vector<RobotWatch> watch;      // per robot of the setup
  int finder = -1;                    // scenario index of the robot that found the ball, -1 = none yet
  int64_t found_tick = 0;             // the tick it was found in
};

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

// Stage 1. Reads the experiment, the trial index and the behaviour hooks;
// writes spec, cell, scenario (with the behaviours; program logs in
// `program_logs` unless "") and the result's header.
TrialState setUpTrial(const Experiment& e, int index, const TrialHooks& hooks, const std::string& program_logs) {
  TrialState s;
  s.spec = trialSpec(e, index);
  s.cell = &e.cell(s.spec.cell);
  s.scenario = trialScenario(e, s.spec);
  hooks.behaviours->configure(*s.cell, s.spec, s.scenario);
  s.result = trialHeader(e, s.spec);
  if (!program_logs.empty()) s.scenario.program_logs = program_logs;
  return s;
}

// Stage 2. Reads spec, cell, scenario; writes runner: started (the t = 0
// penalties: the GameController's placer takes the robots to the sideline),
// then its robots put on their start poses, penalised, as findballexp did
// (they stay there when unpenalised: Return::Sideline).
void startRunner(TrialState& s, const TrialHooks& hooks) {
  const Setup& setup = s.cell->setups[s.spec.setup];
  s.runner = std::make_unique<runner::Runner>(s.scenario);
  // The robot programs' steps on this thread: no hand-over between threads
  // (the same results as named threads; two trials per two cores keep both busy).
  s.runner->programs().setThreading(programs::Threading::Inline);
  hooks.behaviours->attach(*s.cell, s.spec, *s.runner);
  s.runner->start();
  for (size_t i = 0; i < setup.robots.size(); ++i)
    s.runner->placeRobot(static_cast<int>(i), setup.robots[i].x, setup.robots[i].y, setup.robots[i].theta);
  hooks.behaviours->startPlay(*s.cell, s.spec, *s.runner);
}

// Reads cell and the runner's world; the clock's ticks.
TrialClock trialClock(const Experiment& e, const World& w) {
  TrialClock c;
  c.play = playTick(e, w.tickUs());
  c.limit = c.play + w.ticksIn(e.time_limit);
  c.track_every = std::max<int64_t>(1, w.ticksIn(e.track_every));
  c.sideline_ticks = std::max<int64_t>(1, w.ticksIn(e.fallen.sideline_after));
  c.tick_s = w.tickSeconds();
  return c;
}

// A track sample of robot i now. Reads the runner's world and clock; writes
// watch[i].last and the result's tracks (and, if `walked`, the distance
// from the last sample to the robot's walked distance).
void trackSample(TrialState& s, int i, bool walked) {
  const Pose2 p = torsoPose(s.runner->world(), i);
  RobotWatch& r = s.watch[i];
  if (walked) s.result.robots[i].distance_m += std::hypot(p.x - r.last.x, p.y - r.last.y);
  r.last = p;
  s.result.tracks.push_back({i, s.clock.since(s.runner->ticks()), p.x, p.y, p.theta});
}

// Whether no robot but i stands within 0.4 m of (x, y) (m, field frame).
bool spotClear(const World& w, int i, double x, double y) {
  bool clear = true;
  for (int j = 0; j < w.numRobots(); ++j) {
    const Pose2 o = torsoPose(w, j);
    if (j != i && std::hypot(o.x - x, o.y - y) < 0.4) clear = false;
  }
  return clear;
}

// Where a robot down too long goes: its nearest touch line at its x (kept
// inside the field), facing the field; stepped toward the centre line while
// another robot stands within 0.4 m (at most 40 steps).
struct Spot {
  double x, y, theta;  // m, m, rad; field frame
};
Spot sidelineSpot(const Experiment& e, const World& w, int i) {
  const Pose2 p = torsoPose(w, i);
  const double half_l = e.field.length / 2 - 0.3;
  const double side = p.y >= 0 ? 1.0 : -1.0;
  Spot spot{std::max(-half_l, std::min(half_l, p.x)), side * e.field.width / 2, -side * M_PI / 2};
  const double step = spot.x > 0 ? -0.4 : 0.4;
  for (int tries = 0; tries < 40 && !spotClear(w, i, spot.x, spot.y); ++tries) spot.x += step;
  return spot;
}

// Tick stage 2, the fallen-robot rule. Reads cell, clock and the runner's
// world; writes watch (down, down_since, last), the robot's place, the
// result's sideline_moves and, in play, its tracks: the walk up to the
// move counts, the move does not.
void fallenRule(TrialState& s, int64_t tick) {
  World& w = s.runner->world();
  for (int i = 0; i < static_cast<int>(s.watch.size()); ++i) {
    RobotWatch& r = s.watch[i];
    // Falls themselves are counted by the runner, with the same thresholds.
    r.down.update(torsoPose(w, i).z);
    if (!r.down.fallen) {
      r.down_since = -1;
    } else if (r.down_since < 0) {
      r.down_since = tick;
    } else if (tick - r.down_since >= s.clock.sideline_ticks) {
      const Spot spot = sidelineSpot(*s.cell, w, i);
      if (tick > s.clock.play) trackSample(s, i, true);
      s.runner->placeRobot(i, spot.x, spot.y, spot.theta);
      if (tick > s.clock.play) trackSample(s, i, false);  // where it was put (the track jumps here)
      else r.last = torsoPose(w, i);
      ++s.result.robots[i].sideline_moves;
      r.down_since = -1;
    }
  }
}

// Tick stage 3, the found rule (in play). Reads cell, the runner; writes
// finder and found_tick when a robot has found the ball.
void foundRule(TrialState& s, const TrialHooks& hooks, int64_t tick) {
  s.finder = hooks.found->finder(*s.cell, *s.runner);
  if (s.finder >= 0) s.found_tick = tick;
}

// Tick stage 4, the tracks (in play). Reads clock, finder; writes the
// result's tracks and distances: every robot sampled every track_every
// ticks of play and at the trial's last tick (found or the limit), so the
// last leg is sampled. Walked distance is summed over these samples, which
// also averages out the walk's sway.
void sampleTracks(TrialState& s, int64_t tick) {
  if ((tick - s.clock.play) % s.clock.track_every == 0 || s.finder >= 0 || tick == s.clock.limit)
    for (int i = 0; i < static_cast<int>(s.watch.size()); ++i) trackSample(s, i, true);
}

// One tick of the trial, its stages in the order Trial.hpp lists them.
// Until the play tick only 1-2 (the robots are penalised); at its end they
// are unpenalised and the tracks start (each robot's first sample); 3-4
// from the tick after it on.
void trialTick(TrialState& s, const TrialHooks& hooks) {
  s.runner->tick();  // 1.
  const int64_t tick = s.runner->ticks();
  fallenRule(s, tick);  // 2.
  if (tick == s.clock.play)
    for (int i = 0; i < static_cast<int>(s.watch.size()); ++i) trackSample(s, i, false);
  if (tick > s.clock.play) {
    foundRule(s, hooks, tick);  // 3.
    sampleTracks(s, tick);      // 4.
  }
}

// Stage 3. Reads cell, runner; writes clock, watch, finder, found_tick and
// the result's tracks, distances and sideline moves: ticks until a robot
// has found the ball or the time limit's tick has run.
void playUntilFound(TrialState& s, const TrialHooks& hooks) {
  s.clock = trialClock(*s.cell, s.runner->world());
  s.watch.assign(s.cell->setups[s.spec.setup].robots.size(), RobotWatch{});
  while (s.runner->ticks() < s.clock.limit && s.finder < 0) trialTick(s, hooks);
}

// Stage 4. Reads finder, found_tick, clock; writes the result's found,
// seconds (since PLAYING) and finder ("t19p3"); not found: as the header left them.
void classifyOutcome(TrialState& s) {
  if (s.finder >= 0) {
    const ExperimentRobot& r = s.cell->setups[s.spec.setup].robots[s.finder];
    s.result.found = true;
    s.result.seconds = s.clock.since(s.found_tick);
    s.result.finder = common::libagent::robotTag(r.team, r.player);
  }
}

// Stage 5. Reads the runner's statistics; writes the result's resets, falls,
// contact falls and sim_s; the runner shut down and freed.
void recordRunStats(TrialState& s) {
  const runner::RunStats stats = s.runner->stats();
  s.runner->shutdown();
  s.result.resets = stats.blowups;
  for (int i = 0; i < static_cast<int>(s.watch.size()) && i < static_cast<int>(stats.robots.size()); ++i) {
    s.result.robots[i].falls = stats.robots[i].falls;
    s.result.robots[i].contact_falls = stats.robots[i].contact_falls;
  }
  s.result.sim_s = stats.sim_s;
  s.runner.reset();
}

// Instead of stages 2-5 when a launched robot program failed: the runner
// freed, nothing of the partial run kept; the result is the header with the
// brief reason (no pid, no path: results stay a function of the file),
// without the CSV separators. The batch goes on.
void recordFailure(TrialState& s, const Experiment& e, const runner::ProgramError& err) {
  s.runner.reset();
  std::string why = err.brief;
  for (char& c : why)
    if (c == ',' || c == '"') c = ';';
  s.result = trialHeader(e, s.spec);
  s.result.failed = why;
  std::fprintf(stderr, "trial %d failed: %s\n", s.spec.index, err.what());
}

}  // namespace

TrialResult runTrial(const Experiment& e, int index, const TrialHooks& hooks, const std::string& program_logs,
                     const std::string& record_path) {
  const auto wall0 = std::chrono::steady_clock::now();  // timing only
  TrialState s = setUpTrial(e, index, hooks, program_logs);  // 1.
  std::unique_ptr<record::Recorder> rec;  // watches the ticks; changes nothing
  try {
    startRunner(s, hooks);     // 2.
    if (!record_path.empty()) {
      std::filesystem::create_directories(std::filesystem::path(record_path).parent_path());
      rec = std::make_unique<record::Recorder>(record_path);
      s.runner->addObserver(rec.get());
      rec->begin(*s.runner);
    }
    playUntilFound(s, hooks);  // 3.
    classifyOutcome(s);        // 4.
    recordRunStats(s);         // 5.
  } catch (const runner::ProgramError& err) {
    recordFailure(s, e, err);
  }
  if (rec) {
    if (s.runner) s.runner->removeObserver(rec.get());
    rec->finish();
  }
  s.result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();  // 6.
  return s.result;
}

std::unique_ptr<runner::Runner> startTrial(const Experiment& e, int index, const TrialHooks& hooks) {
  TrialState s = setUpTrial(e, index, hooks, "");  // 1.
  startRunner(s, hooks);                           // 2.
  return std::move(s.runner);
}

}  // namespace simswift::experiment
