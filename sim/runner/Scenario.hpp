// A run's description, loaded from YAML (scenarios/*.yaml):
//
//   model: models/nao_v5.urdf      # optional; relative to this file's folder, then the data folder
//   field: fields/spl_2017.yaml    # optional
//   duration: 10                   # s of simulated time
//   seed: 1
//   noise: on                      # or off, or a map of per-sensor switches:
//                                  # {gyro, accel, angle, fsr, sonar, encoder: on/off}
//   inertial: {gyr_raw_sign: 1, acc_raw_sign: 1}   # the V5's raw GyrX/Y and AccX/Y/Z against
//                                  # the calibrated slots: +1 same sign (default), -1 opposite
//                                  # (no public source settles it: docs/libagent.md, Inertial sensors)
//   watchdog: 5                    # s of wall clock a robot thread may take, or off
//   attach_timeout: 30             # s of wall clock to wait for external robots
//   program_logs: simswift-logs    # folder of launched programs' logs (<tag>.log) and setups
//   base_dir: /path/to/simswift    # optional; where relative model/field paths resolve first
//   physics: {substeps: 3, solver: quick|exact, iterations: 20}  (defaults: WorldConfig;
//                                  substeps per tick, default: steps of at most 5 ms)
//   camera:                        # rendering is off unless asked (here or by CLI flags)
//     enabled: on                  # render both NAO cameras of every robot at 30 Hz
//     resolution: 640x480          # or 1280x960
//     overview: {mode: fixed|robot|ball, robot: 0, rate_hz: 10,
//                width: 960, height: 540, dir: overview}   # whole-field PNGs (+ MP4)
//   vision: {ball: {max_distance_mm: 2500, false_positive_rate: 0.01}, ...}
//                                  # detector model (sim/vision/VisionConfig.hpp); or on/off
//   ball: {x: 1.0, y: 0.0}         # m, field frame (default: the centre spot)
//   ball: none                     # no ball in the world (nobody can see one)
//   robots:
//     - {team: 19, player: 1, x: -1.0, y: 0.0, theta: 0.0,  # m, m, rad (field frame)
//        colour: blue,                 # side of the match (blue or red), see below
//        names: simulation,            # libagent names: simulation (N = team x 11 + player) or bare
//        libagent: {release: 2017, start: stiff},  # the body interface: libagent, the NAO V5 (default), or
//        lola: {socket: /tmp/x.sock},  # LoLA, the NAO V6 (socket default /tmp/simswift-lola/t<T>p<P>;
//                                      # names: bare serves /tmp/robocup); all robots of a run alike
//        posture: stand, program: builtin,   # or external, or {command: [...]} (sim/programs/ProgramProcess.hpp)
//        script: [{t: 2.0, joint: HeadYaw, angle: 0.5, duration: 0.5}],
//        buttons: [{t: 3.0, button: chest, duration: 0.1}],
//        actions: [{t: 1.0, action: walk, forward: 300, left: 0, turn: 0},  # mm/s, rad/s
//                  {t: 6.0, action: kick, foot: right, power: 1, direction: 0},
//                  {t: 9.0, push: {x: 3.0, y: 0.0}}]}   # impulse N*s at the torso (field axes)
//      actions run the robot's Motion (agent/motion) from a timed list: walk, stand,
//      kick, getup_front, getup_back, dead, crouch, limp, none.
//      behaviour: findball2017 | findball2016 | striker | script (default), or a map
//        {kind: findball2017, strategy: {distributed: off}, ...} overriding
//        agent/behaviour/BehaviourConfig.hpp's fields (agent/behaviour/BehaviourYaml.hpp).
//        script runs the actions list; the others run agent/behaviour, the
//        localisation starting at the scenario's pose (a known start, as on a
//        test field where the team places its robots).
//   team_comms: {loss: 0.1, delay_ms: 100, budget: 0}   # see sim/network/TeamNetwork.hpp
//      loss 0..1 per packet and teammate, delay ms, budget packets per team per game (0 = none)
//   game:                          # the GameController (sim/game); absent = PLAYING throughout
//     state: initial               # state at t = 0 (default playing)
//     kickoff_team: 0              # team index
//     half_duration: 600           # s
//     on_unpenalise: previous      # or sideline: where an unpenalised robot goes
//     timeline: [{t: 0, state: ready}, {t: 45, state: set}, {t: 50, state: playing, kickoff_team: 1}]
//     penalties: [{t: 10, robot: 0, penalty: request_for_pickup, duration: 30}]  # robot: scenario index;
//                                  # duration s (< 0: until {penalty: none}); penalised robots wait on the sideline
//     udp: on                      # also send the SPL 2017 GameController packets (sim/game/GameControllerUdp.hpp)
//     port: 3838                   # their UDP port; return_port: 3939 (0 = any free); address: 127.0.0.1 (loopback only)
//
// `team` is the SPL team number (0..255, as in the GameController). A match
// has at most two teams, told apart by colour: a robot's `colour` (blue or
// red) defaults to blue for the first team number in the file and red for
// the second; all robots of a team share one colour, the two teams differ.
// The game (GameController, sideline, team network) knows the teams by
// side: blue is team index 0 (own goal at -x), red index 1.
// `names: bare` gives one robot the robot build's /libagent-memory and
// /libagent-semaphore.
//
// Unknown keys and bad values throw ConfigError naming file, line and key:
//   scenario.yaml:7: robots[1].team: must be in [0, 255] (got 300)
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "agent/nao/Postures.hpp"
#include "sim/bridge/BodySide.hpp"
#include "sim/game/GameController.hpp"
#include "sim/bridge/LibagentBehaviour.hpp"
#include "sim/bridge/Releases.hpp"
#include "sim/network/TeamNetwork.hpp"
#include "sim/programs/ProgramProcess.hpp"
#include "sim/programs/ProgramSpec.hpp"
#include "sim/sensors/Buttons.hpp"
#include "sim/sensors/SensorConfig.hpp"
#include "sim/vision/VisionConfig.hpp"
#include "sim/world/ConfigError.hpp"
#include "sim/world/FieldConfig.hpp"
#include "sim/world/World.hpp"

namespace agent::config {
class YamlReader;
}
namespace simswift {
using agent::config::YamlReader;
}

namespace simswift::runner {

enum class TeamColour : int { Blue = 0, Red = 1 };

using programs::LaunchSpec;

// One robot: the body's fields here, the program's part (script, actions,
// behaviour: what a program simswift composes or configures is set up
// with) in programs::ProgramPart, read by sim/programs' readers.
struct RobotSpec : programs::ProgramPart {
  int line = 0;  // of the robot's entry in the scenario file (for errors)
  int team = 0;    // SPL team number
  int player = 1;
  TeamColour colour = TeamColour::Blue;  // side of the match
  bool bare_names = false;               // /libagent-memory without suffix
  // libagent: {start: stiff | limp, release: 2016 | 2017 | 2018}: how the
  // body side starts (sim/bridge/LibagentBehaviour.hpp) and which rUNSWift
  // release's block and names it serves (sim/bridge/Releases.hpp).
  bridge::StartMode start = bridge::StartMode::Stiff;
  bridge::Release release = bridge::Release::R2017;
  // The body interface (libagent: the NAO V5 at 10 ms; lola: the NAO V6 at
  // 12 ms, sim/lola/LolaBody.hpp) and, for lola, its socket.
  bridge::BodyInterface body = bridge::BodyInterface::Libagent;
  std::string lola_socket;  // absolute path; empty: one of the process's own (an experiment's trial)
  double x = 0, y = 0, theta = 0;  // m, m, rad; field frame
  agent::nao::Posture posture = agent::nao::Posture::Stand;
  // builtin: agent/'s program in this process; external: a program
  // attached by name (started by hand, or by simswift when `launch` has a
  // command: sim/programs/ProgramProcess.hpp). What drives the body either
  // way: sim/programs/ProgramDriver.hpp.
  enum class Program { Builtin, External } program = Program::Builtin;
  LaunchSpec launch;
  // Pushes from the actions list, e.g. {t: 9, push: {x: 2.5, y: 0}}: an
  // impulse of (x, y) N*s (field frame) at the torso's centre of mass at
  // time t (simulator side, World::applyImpulse): 1 N*s changes the 5.3 kg
  // NAO's CoM velocity by 0.19 m/s; about 3.5 N*s topples a standing NAO.
  struct Push { double t_s = 0, jx = 0, jy = 0; };  // s, N*s, N*s
  std::vector<Push> pushes;
  // Touch sensors pressed by the scenario (any program), e.g.
  //   buttons: [{t: 2.0, button: chest, duration: 0.1}]
  // held from t for duration s (chest, head_front, head_middle, head_rear);
  // also from actions: {t: 5, click: chest, count: 2} (clicks of 0.1 s
  // down, 0.1 s up) and {t: 9, press: chest, for: 3.2}.
  struct ButtonPress { double t_s = 0, duration_s = 0.1; sensors::Button button = sensors::Button::Chest; };
  std::vector<ButtonPress> buttons;
  bool buttonHeld(sensors::Button b, double t_s) const;  // any press of b covers t_s
};

// Camera rendering. Off unless a scenario or flag asks.
struct CameraSpec {
  bool enabled = false;            // robot cameras into each robot's CameraImages
  int width = 640, height = 480;   // px: 640x480 or 1280x960
  std::string dump_dir;            // --dump-frames DIR (implies rendering); empty = none
  int dump_every = 1;              // --every N: camera frames between dumps
  struct Overview {
    bool enabled = false;
    enum class Mode { Fixed, Robot, Ball } mode = Mode::Fixed;
    int robot = 0;                 // scenario robot index (mode robot)
    double rate_hz = 10;           // frames per simulated second
    int width = 960, height = 540; // px, even
    std::string dir = "overview";  // PNG folder (+ overview.mp4 with ffmpeg)
  } overview;

  bool renderRobots() const { return enabled || !dump_dir.empty(); }
  bool any() const { return renderRobots() || overview.enabled; }
};

struct NoiseSwitches {
  bool on = true;  // master switch
  bool gyro = true, accel = true, angle = true, fsr = true, sonar = true, encoder = true;
};

struct Scenario {
  std::string source = "<defaults>";
  std::string model_path;   // absolute, or relative to base_dir, then to the data folders
  std::string field_path;
  int model_line = 1, field_line = 1;  // where they were given (for errors)
  bool model_named = false;             // the file has `model:` (else a V6 run takes the V6's)
  std::string base_dir;     // where relative paths resolve first (the scenario's folder)
  double duration = 10.0;   // s
  uint64_t seed = 1;
  NoiseSwitches noise;
  // `inertial:`; defaults are SensorConfig's (sim/sensors/SensorConfig.hpp).
  int gyr_raw_sign = sensors::SensorConfig{}.gyr_raw_sign;
  int acc_raw_sign = sensors::SensorConfig{}.acc_raw_sign;
  double watchdog_s = 5.0;        // wall-clock s per robot thread answer; 0 = off (watchdog: off)
  double attach_timeout_s = 30.0; // wall-clock s to wait for external robots
  std::string program_logs = "simswift-logs";  // launched programs' logs (relative: to the working folder)
  // Physics defaults follow WorldConfig (QuickStep, steps of at most 5 ms:
  // 2 per 10 ms tick, 3 per 12 ms; World.cpp says why).
  int substeps = WorldConfig{}.substeps;  // 0: WorldConfig's rule
  std::string solver = WorldConfig{}.solver == WorldConfig::Solver::Quick ? "quick" : "exact";
  int quick_iterations = WorldConfig{}.quick_iterations;
  CameraSpec camera;
  // The vision oracle's detector model (`vision:`). Its noise is off too
  // when the scenario's noise master switch is off (see Runner::start).
  vision::VisionConfig vision;
  std::optional<std::pair<double, double>> ball;  // m, field frame
  bool no_ball = false;                           // `ball: none`
  int ball_line = 0;
  std::vector<RobotSpec> robots;
  // us per tick: the robots' body interface's cycle (all robots alike;
  // sim/runner/Bodies.hpp bodyCycleUs), World's tick.
  int64_t tick_us = agent::nao::kMotionTickUs;
  network::TeamNetworkConfig team_comms;  // team_comms: (defaults: no loss, no delay, no budget)
  game::GameConfig game;                  // game: (default: PLAYING, no penalties)

  // Placement checked against the field (ConfigError "file:line: key: ..."):
  // every robot and the ball on the carpet, not inside a goal post, robots
  // not overlapping one another. Runner::start() calls it.
  void checkAgainstField(const FieldConfig& field) const;

  // The model and field files: a relative path is looked up in base_dir,
  // then in dataDirs(). ConfigError (file:line) if none has it.
  std::string modelFile() const;
  std::string fieldFile() const;
  std::string locate(const std::string& path, const std::string& key, int line) const;

  static Scenario loadFile(const std::string& path);
  static Scenario parse(const std::string& text, const std::string& source_name);
  // A scenario map inside another file (a scenario test's `scenario:`):
  // errors name that file and the map's key path; relative paths resolve
  // against source_name's folder.
  static Scenario read(const YamlReader& top, const std::string& source_name);
};

// A robot entry's `actions:` list into rs.actions and rs.pushes (also the
// experiment files' script robots, sim/experiment).
void readActions(const YamlReader& robot, RobotSpec& rs);

// A robot entry's `program:` (builtin, external, or {command: [...], cwd,
// env, stop_grace}) into rs.program and rs.launch; relative paths resolve
// against base_dir (also the experiment files' robots). Its placeholders are
// checked against the robot's body (a `lola:` robot's or libagent's);
// any_body: against either (an experiment setup's default program, whose
// robots say which; a wrong one is refused when the trial launches it).
void readProgram(const YamlReader& robot, RobotSpec& rs, const std::string& base_dir, bool any_body = false);

// The scenario's settings blocks, one reader each (also the experiment
// files' base settings and their sweeps, sim/experiment): `noise:` (on/off
// or a map of switches; absent: unchanged), `physics:` (absent: unchanged),
// `team_comms:` and `game:` (a map each; num_robots: the robots a penalty
// may name).
void readNoise(const YamlReader& top, NoiseSwitches& noise);
void readPhysics(const YamlReader& top, Scenario& sc);
network::TeamNetworkConfig readTeamComms(const YamlReader& r);
game::GameConfig readGame(const YamlReader& r, int num_robots);

// Robots closer than two robot radii: ConfigError naming the second's line
// (Scenario::parse calls it; so does a scenario test for its fuzzed starts).
void checkRobotsApart(const Scenario& sc);

// The seed of robot `index`'s program (its filters' random source) in a
// run with seed `seed`: one derivation for builtin and launched programs.
uint64_t programSeed(uint64_t seed, int index);

// Where relative model/field paths resolve after the scenario's folder:
// $SIMSWIFT_DATA_DIR if set, else the nearest share/simswift in the folder of
// the file holding this code (libsimswift.so, or the executable linking it
// statically), its parent or its grandparent (docs/library.md). One folder
// when found; the candidates tried when none exists.
std::vector<std::string> dataDirs();

}  // namespace simswift::runner
