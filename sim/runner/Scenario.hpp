// A run's description, loaded from YAML (scenarios/*.yaml):
//
//   model: models/nao_v5.urdf      # optional; relative to the source tree
//   field: fields/spl_2017.yaml    # optional
//   duration: 10                   # s of simulated time
//   seed: 1
//   noise: on                      # or off, or a map of per-sensor switches:
//                                  # {gyro, accel, angle, fsr, sonar, encoder: on/off}
//   watchdog: 5                    # s of wall clock a robot thread may take
//   attach_timeout: 30             # s of wall clock to wait for external robots
//   base_dir: /path/to/simswift    # optional; where relative model/field paths resolve
//   physics: {substeps: 2, solver: quick|exact, iterations: 20}  (defaults: WorldConfig)
//   camera: {enabled: off, ...}    # reserved for the camera issue
//   ball: {x: 1.0, y: 0.0}         # m, field frame
//   robots:
//     - {team: 0, player: 1, x: -1.0, y: 0.0, theta: 0.0,   # m, m, rad (field frame)
//        posture: stand, program: builtin,
//        script: [{t: 2.0, joint: HeadYaw, angle: 0.5, duration: 0.5}]}
//
// Unknown keys and bad values throw ConfigError naming file, line and key:
//   scenario.yaml:7: robots[1].team: must be 0..1 (got 3)
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "agent/program/MotionGenerator.hpp"
#include "agent/program/Postures.hpp"
#include "sim/world/ConfigError.hpp"
#include "sim/world/World.hpp"

namespace simswift::runner {

struct RobotSpec {
  int team = 0;
  int player = 1;
  double x = 0, y = 0, theta = 0;  // m, m, rad; field frame
  agent::program::Posture posture = agent::program::Posture::Stand;
  enum class Program { Builtin, External } program = Program::Builtin;
  std::vector<agent::program::ScriptStep> script;
};

struct NoiseSwitches {
  bool on = true;  // master switch
  bool gyro = true, accel = true, angle = true, fsr = true, sonar = true, encoder = true;
};

struct Scenario {
  std::string source = "<defaults>";
  std::string model_path;   // absolute or relative to base_dir
  std::string field_path;
  std::string base_dir;     // where relative paths resolve (the source tree)
  double duration = 10.0;   // s
  uint64_t seed = 1;
  NoiseSwitches noise;
  double watchdog_s = 5.0;        // wall-clock s per robot thread answer
  double attach_timeout_s = 30.0; // wall-clock s to wait for external robots
  // Physics defaults follow WorldConfig (QuickStep, 2 x 5 ms; World.cpp says why).
  int substeps = WorldConfig{}.substeps;
  std::string solver = WorldConfig{}.solver == WorldConfig::Solver::Quick ? "quick" : "exact";
  int quick_iterations = WorldConfig{}.quick_iterations;
  bool camera = false;
  std::optional<std::pair<double, double>> ball;  // m, field frame
  std::vector<RobotSpec> robots;

  // Absolute paths of the model and field files.
  std::string modelFile() const;
  std::string fieldFile() const;

  static Scenario loadFile(const std::string& path);
  static Scenario parse(const std::string& text, const std::string& source_name);
};

// The source tree (compile definition), where default paths resolve.
std::string sourceDir();

}  // namespace simswift::runner
