// A find-ball experiment (thesis §3.2.6 findballexp and §5.1), loaded from
// YAML and validated in full before any trial runs:
//
//   name: thesis_findball          # names the results folder and the report
//   field: fields/spl_2017.yaml    # optional (as in a scenario)
//   model: models/nao_v5.urdf      # optional
//   seed: 2017                     # trial seeds derive from (seed, trial index)
//   time_limit: 180                # s of simulated time per trial (> 0)
//   trials_per_position: 10
//   start: {penalised: 1.0}        # s the robots stand penalised at their start
//                                  # poses before the trial's clock starts (PLAYING)
//   found: {distance: 0.300, sees: true, seen_frames: 5}   # m (inclusive, >= ball
//                                  # radius); sees: the robot's vision (the oracle's
//                                  # detector model, as its perception gets it) reports
//                                  # the true ball in the latest seen_frames camera
//                                  # frames in a row (default 1), the latest at that
//                                  # distance or less
//   fallen: {sideline_after: 30}   # s down (not got up) before the robot is moved
//                                  # to the sideline, as the thesis did
//   tracks: {every: 0.5}           # s between robot track samples
//   noise: on                      # sensor noise (the scenario's noise: switch or map)
//   vision: {ball: {max_distance_mm: 2500}}   # detector model and noise: the
//                                  # scenario's vision: block (sim/vision/VisionConfig.hpp),
//                                  # read by its reader, given to every trial
//   team_comms: {loss: 0.1}        # the scenario's blocks, read by its readers
//   physics: {substeps: 2}         # (docs/runner.md), given to every trial;
//   game: {half_duration: 600}     # game: only kickoff_team, half_duration, first_half
//                                  # (each trial sets the rest: penalised, then PLAYING)
//   sweep:                         # optional: values by dotted path (Sweep.hpp); every
//     team_comms.loss: [0, 0.3]    # combination is a cell that runs every trial above
//     setups.2017.config.search.spin_at_point: [on, off]
//   balls:                         # table 5.2 (m, field frame)
//     - {position: 1, x: 2.25, y: 0.0, note: Right middle}
//   setups:                        # each runs every ball position x trials_per_position
//     - name: "2016"
//       thesis_table: "5.3"        # optional: the thesis table it repeats (report columns)
//       behaviour: findball2016    # default for the robots below
//       config: {...}              # default behaviour overrides (opaque)
//       program: {command: [simswift-agent, --config, "{config}"]}   # optional, also
//                                  # per robot: a program launched fresh for every
//                                  # trial (sim/programs/ProgramProcess.hpp; default builtin)
//       robots:                    # table 5.1: SPL team and player numbers, start poses
//         - {team: 19, player: 2, x: -3.25, y: 3.0, theta: -1.5708}
//         - {team: 19, player: 3, x: -2.0, y: -3.0, theta: 1.5708, behaviour: script,
//            actions: [{t: 0.5, action: walk, forward: 250}]}   # script: the scenario's actions
//
// A trial starts as the thesis's experiment controller started its tests
// (findballexp, §3.2.6 and §5.1): the robots are penalised (game state
// INITIAL) and stand at their start poses, the ball lies at its position,
// their programs start with no ball knowledge; after `start.penalised` s
// the game goes to PLAYING and every robot is unpenalised at once. Find
// times and the time limit count from that moment.
//
// Trials are numbered cell-major, then setup-major: trial = cell *
// trialsPerCell() + (setup * positions + position) * trials_per_position +
// repeat (one cell without a sweep). Every error is a ConfigError naming
// file, line and field.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/experiment/Sweep.hpp"
#include "sim/programs/ProgramSpec.hpp"
#include "sim/runner/Scenario.hpp"
#include "sim/world/ConfigError.hpp"
#include "sim/world/FieldConfig.hpp"

namespace simswift::experiment {

// Trials one experiment file may ask for (cells x setups x positions x
// trials per position); more is refused when it is loaded.
constexpr int64_t kMaxTrials = 1000000;


struct BallPosition {
  int number = 1;          // the thesis's position number (table 5.2)
  double x = 0, y = 0;     // m, field frame
  std::string note;
};

struct ExperimentRobot {
  int team = 0;            // SPL team number (GameController byte, 0..255), e.g. 19
  int player = 2;          // 1..5
  double x = 0, y = 0, theta = 0;  // m, m, rad; field frame
  // A scenario's `behaviour:` name (programs::behaviourNames(): the robot
  // program's kinds, or script). Whether this build can run it is the
  // BehaviourFactory's call (TrialHooks).
  std::string behaviour = programs::kScriptBehaviour;
  bool isScript() const { return behaviour == programs::kScriptBehaviour; }
  std::string config_yaml;  // behaviour overrides, opaque (YAML flow text; "" = none)
  runner::RobotSpec script;  // behaviour script: its actions (the scenario's actions: list)
  // program: builtin (default) or {command: [...]}: a program simswift
  // starts fresh for every trial (sim/programs/ProgramProcess.hpp), given the
  // robot's setup in its {config} file.
  runner::LaunchSpec launch;
  // lola: {}: a NAO V6 over LoLA at 12 ms (docs/lola.md), its socket private
  // to the trial's process; every robot of a setup alike.
  bool v6 = false;
  ConfigPlace behaviour_where;  // its behaviour key (or its setup's), for the later override errors
};

struct Setup {
  std::string name;
  std::string thesis_table;  // "5.3".."5.8" or ""
  std::vector<ExperimentRobot> robots;
};

struct FoundSpec {
  // m, inclusive. With `sees`, the distance the robot's vision measured (the
  // oracle's detection: from the point between its feet to the ball, with
  // the detector's noise, as the thesis's controller took the robot's own
  // estimate); without, the true ground distance from that point.
  double distance = 0.300;
  bool sees = true;  // the robot's vision reports the (true) ball in the latest frame
  // With `sees`: camera frames in a row (ending with the latest) in which
  // the robot saw the ball. The thesis's controller (jcol2/findballexp)
  // waited for a robot's ball_seen_count >= 5; 1 = the latest frame alone.
  int seen_frames = 1;
};

// The found rule for one robot: its latest sighting of the true ball
// (frame, measured distance, frames in a row), the latest camera frame, and
// (without `sees`) its true ground distance to the ball (m).
bool foundBy(const FoundSpec& f, int64_t sighting_frame, double sighting_distance_m, int consecutive,
             int64_t last_frame, double true_distance_m);

struct StartSpec {
  double penalised = 1.0;  // s penalised at the start poses before PLAYING (0.05..60)
};

struct FallenSpec {
  double sideline_after = 30.0;  // s continuously down before the move
};

struct Experiment {
  std::string source;        // file name, for messages
  std::string text;          // the file's text (copied into the results folder)
  std::string name;
  runner::Scenario base;     // model, field, base_dir, noise: the trial scenarios' common part
  FieldConfig field;
  uint64_t seed = 1;
  double time_limit = 180;   // s
  int trials_per_position = 1;
  StartSpec start;
  FoundSpec found;
  FallenSpec fallen;
  double track_every = 0.5;  // s
  std::string vision_yaml;   // the vision: block as written (YAML flow text; "" = none);
                             // parsed into base.vision
  std::vector<BallPosition> balls;
  std::vector<Setup> setups;
  // sweep: its paths and values, and one experiment per cell (the base with
  // the cell's values applied, validated). Both empty without a sweep.
  std::vector<SweepAxis> sweep;
  int sweep_line = 0;  // of the sweep: key
  std::vector<std::shared_ptr<const Experiment>> cells;

  bool swept() const { return !cells.empty(); }
  int numCells() const { return cells.empty() ? 1 : static_cast<int>(cells.size()); }
  // Cell c's experiment (this one without a sweep).
  const Experiment& cell(int c) const { return cells.empty() ? *this : *cells[c]; }
  // Counted in 64 bits: a file's product (250 setups x 1000 positions x
  // 10000 trials) overflows an int before the loader can refuse it.
  int64_t countTrialsPerCell() const {
    return static_cast<int64_t>(setups.size()) * static_cast<int64_t>(balls.size()) * trials_per_position;
  }
  int64_t countTrials() const { return numCells() * countTrialsPerCell(); }
  // The same as int: a loaded experiment has at most kMaxTrials.
  int trialsPerCell() const { return static_cast<int>(countTrialsPerCell()); }
  int numTrials() const { return static_cast<int>(countTrials()); }
  int maxRobots() const;

  static Experiment loadFile(const std::string& path);
  static Experiment parse(const std::string& text, const std::string& source_name);
};

// Which cell, setup, ball position and repeat a trial index is, and its
// seed. The seed depends on the index within the cell only: every cell
// draws the same noise (a difference between cells is the swept setting's).
struct TrialSpec {
  int index = 0;
  int cell = 0;        // index into Experiment::cells (0 without a sweep)
  int setup = 0;       // index into Experiment::setups
  int ball = 0;        // index into Experiment::balls
  int repeat = 0;      // 0..trials_per_position-1
  uint64_t seed = 0;   // < 2^31: the trial seeds results.csv has always published (DeriveSeed.hpp kTrial)
};
TrialSpec trialSpec(const Experiment& e, int index);

// The scenario of one trial (of its cell's experiment) without behaviours: robots standing at their
// start poses, ball placed, seed set, the game (penalised in INITIAL, then
// PLAYING and unpenalised at playTicks), duration = start + time limit.
// The BehaviourFactory then fills in each robot's behaviour.
runner::Scenario trialScenario(const Experiment& e, const TrialSpec& t);

// The tick at whose end the robots are unpenalised and PLAYING begins; the
// trial's clock counts from it. tick_us: the setup's robots' (10 ms on the
// V5, 12 ms on the V6: setupTickUs).
int64_t playTick(const Experiment& e, int64_t tick_us = common::nao::kMotionTickUs);
// The tick of a setup's robots, us (sim/runner/Bodies.hpp).
int64_t setupTickUs(const Setup& s);

// The side of the match a setup's team plays on: the first team number in
// the setup blue, a second one red (the scenario's own default).
runner::TeamColour teamColour(const Setup& s, int spl_team);

}  // namespace simswift::experiment
