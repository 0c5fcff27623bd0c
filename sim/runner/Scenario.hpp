// A run's description, loaded from YAML (scenarios/*.yaml). The file's
// keys, their units and defaults are documented once, in docs/runner.md
// ("The scenario file"); the defaults themselves live in the structs below
// (and the ones they hold: WorldConfig, GameConfig, ...), which the reader
// starts from.
//
// Unknown keys and bad values throw ConfigError naming file, line and key:
//   scenario.yaml:7: robots[1].team: must be in [0, 255] (got 300)
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/clock/ClockPage.hpp"
#include "common/libagent/CameraImages.hpp"
#include "common/nao/Postures.hpp"
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

namespace common::config {
class YamlReader;
}
namespace simswift {
using common::config::YamlReader;
}

namespace simswift::runner {

enum class TeamColour : int { Blue = 0, Red = 1 };

// s: the most a wall-clock setting may be (watchdog, attach timeout).
constexpr double kMaxWallClockS = 3600;

// The model of a run whose robots have a LoLA body, unless it names one.
constexpr const char* kV6Model = "models/nao_v6.urdf";

using programs::LaunchSpec;

// One robot: the body's fields here; what its program does (script,
// actions, behaviour: for a program simswift composes or configures) in
// `setup`, the agent's own RobotSetup, read by its parser
// (sim/programs/ProgramSpec.hpp).
struct RobotSpec {
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
  double x = 0, y = 0, theta = 0;  // m, m, rad; field frame (a behaviour's start pose too)
  common::nao::Posture posture = common::nao::Posture::Stand;  // the body's start; a composed program holds it
  // builtin or external (sim/programs/ProgramSpec.hpp ProgramKind; launched
  // by simswift when `launch` has a command). What drives the body either
  // way: sim/programs/ProgramDriver.hpp.
  using Program = programs::ProgramKind;
  Program program = Program::Builtin;
  LaunchSpec launch;
  programs::ProgramPart setup;  // script, actions, behaviour (its identity: programs::robotSetup)
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
  // The robot's cameras as V4L2 devices for its launched program, or its
  // external one started by hand (`simswift attach`; docs/porting.md
  // section 3; sim/bridge/V4l2Devices.hpp):
  //   v4l2: {top: /dev/video-top, bottom: /dev/video-bottom}   the paths it opens
  //   v4l2: on | off
  // Absent: on for a launched or external program in a build with cameras (at the
  // body's names: a V6's /dev/video-top and /dev/video-bottom, a V5's
  // /dev/video0 (top) and /dev/video1 (bottom)), else off.
  struct CameraDevices {
    enum class Mode { Default, On, Off } mode = Mode::Default;
    std::array<std::string, 2> path;  // top, bottom: under /dev/; empty: the body's (defaultCameraDevices)
  };
  CameraDevices v4l2;
};

// The NAO's camera device names (top, bottom): a V6's /dev/video-top and
// /dev/video-bottom (B-Human, rUNSWift 2022), a V5's /dev/video0 and
// /dev/video1 (every V5 build).
std::array<std::string, 2> defaultCameraDevices(bridge::BodyInterface body);

// Camera rendering. Off unless a scenario or flag asks.
struct CameraSpec {
  bool enabled = false;            // robot cameras into each robot's CameraImages
  // Each robot camera's size (index 0 top, 1 bottom; cameraResolutions();
  // ImageSize's default, 640x480).
  common::libagent::ImageSize resolution[common::libagent::kNumCameras];
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

// The robot camera sizes a scenario's camera.resolution or --resolution may
// name: "640x480" and "1280x960".
const std::vector<std::pair<std::string, common::libagent::ImageSize>>& cameraResolutions();
// The size `name` ("640x480") spells, if it is one of cameraResolutions().
std::optional<common::libagent::ImageSize> cameraResolution(const std::string& name);

struct NoiseSwitches {
  bool on = true;  // master switch
  bool gyro = true, accel = true, angle = true, fsr = true, sonar = true, encoder = true;
};

struct Scenario {
  std::string source = "<defaults>";
  std::string model_path = "models/nao_v5.urdf";  // absolute, or relative to base_dir, then to the data folders
  std::string field_path = "fields/spl_2017.yaml";  // (a V6 run's model: kV6Model)
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
  // `clock_epoch:` a launched or external program's REALTIME at t = 0, s
  // since 1970 UTC (docs/shim.md; default 2025-07-15T00:00:00Z).
  int64_t clock_epoch_s = common::clock::kDefaultRealtimeEpochNs / 1'000'000'000;
  // The World's settings: `physics:` (checked by checkWorldConfig, the
  // World's own rules) and tick_us, the us per tick of the robots' body
  // interface (all robots alike; sim/runner/Bodies.hpp bodyCycleUs).
  WorldConfig world;
  CameraSpec camera;
  // The vision oracle's detector model (`vision:`). Its noise is off too
  // when the scenario's noise master switch is off (see Runner::start).
  vision::VisionConfig vision;
  std::optional<std::pair<double, double>> ball;  // m, field frame
  bool no_ball = false;                           // `ball: none`
  int ball_line = 0;
  std::vector<RobotSpec> robots;
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

// A robot entry's `actions:` list into rs.setup.actions, rs.pushes and
// rs.buttons (also the experiment files' script robots, app/experiment).
void readActions(const YamlReader& robot, RobotSpec& rs);

// A robot entry's `program:` (builtin, external, or {command: [...], cwd,
// env, stop_grace}) into rs.program and rs.launch; relative paths resolve
// against base_dir (also the experiment files' robots). Its placeholders are
// checked against the robot's body (a `lola:` robot's or libagent's);
// any_body: against either (an experiment setup's default program, whose
// robots say which; a wrong one is refused when the trial launches it).
void readProgram(const YamlReader& robot, RobotSpec& rs, const std::string& base_dir, bool any_body = false);

// The scenario's settings blocks, one reader each (also the experiment
// files' base settings and their sweeps, app/experiment): `noise:` (on/off
// or a map of switches; absent: unchanged), `physics:` (absent: unchanged),
// `team_comms:` and `game:` (a map each; num_robots: the robots a penalty
// may name).
void readNoise(const YamlReader& top, NoiseSwitches& noise);
void readPhysics(const YamlReader& top, WorldConfig& world);
network::TeamNetworkConfig readTeamComms(const YamlReader& r);
game::GameConfig readGame(const YamlReader& r, int num_robots);

// Robots closer than two robot radii: ConfigError naming the second's line
// (Scenario::parse calls it; so does a scenario test for its fuzzed starts).
void checkRobotsApart(const Scenario& sc);

// The seed of robot `index`'s program (its filters' random source) in a
// run with seed `seed`: one derivation for builtin and launched programs.
uint64_t programSeed(uint64_t seed, int index);

// What robot `index` of `sc` gives its program (team, player, programSeed,
// posture, start pose, whether it is pushed): with its program part, its
// setup (programs::robotSetup), the same for builtin and launched programs.
programs::ProgramIdentity programIdentity(const Scenario& sc, int index);

// Where relative model/field paths resolve after the scenario's folder:
// $SIMSWIFT_DATA_DIR if set, else the nearest share/simswift in the folder of
// the file holding this code (libsimswift.so, or the executable linking it
// statically), its parent or its grandparent (docs/library.md). One folder
// when found; the candidates tried when none exists.
std::vector<std::string> dataDirs();

}  // namespace simswift::runner
