// The SPL field as typed configuration, loaded from YAML (fields/*.yaml).
// Every struct has defaults equal to the SPL 2017 rules, so a YAML file only
// needs what it changes; an unknown key, a missing required field or a bad
// value throws ConfigError naming the file, line and key.
//
// Frame: field frame, origin at the centre spot, x toward the opponent
// (positive) goal, y left, z up. Units: m, kg, rad.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace simswift {

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct LineSegment {   // a painted line, from a to b, `width` wide
  double ax = 0, ay = 0, bx = 0, by = 0;
  double width = 0.05;
};
struct LineCircle {    // the centre circle: the painted band is `width` wide
  double cx = 0, cy = 0, radius = 0.75;
  double width = 0.05;
};
struct LineCross {     // penalty marks: a cross `size` across, lines `width` wide
  double x = 0, y = 0, size = 0.1, width = 0.05;
};

struct GoalConfig {
  double post_diameter = 0.10;   // posts and crossbar
  double post_height = 0.80;     // to the top of the crossbar
  double inner_width = 1.50;     // between the posts' inner faces
  double depth = 0.50;           // net depth behind the goal line
  double net_height = 0.80;
};

struct BallConfig {
  double diameter = 0.10;
  double mass = 0.044;
  double rolling_friction = 0.02;   // rolling-resistance coefficient on carpet (dimensionless)
  double restitution = 0.6;         // against posts and robots
  double linear_damping = 0.0;      // extra air drag (1/s)
};

struct SurfaceConfig {
  double friction = 0.8;            // foot-carpet Coulomb coefficient
  double ball_friction = 0.5;       // ball-carpet
  double soft_erp = 0.2, soft_cfm = 1e-5;
};

struct FieldConfig {
  std::string source = "<defaults>";  // file it came from, for messages
  double length = 9.0;          // between the goal lines' centres (m)
  double width = 6.0;           // between the touch lines' centres (m)
  double border = 0.7;          // carpet beyond the lines (m)
  double line_width = 0.05;
  std::vector<LineSegment> lines;
  std::vector<LineCircle> circles;
  std::vector<LineCross> crosses;
  GoalConfig goal;
  BallConfig ball;
  SurfaceConfig surface;

  double carpetLength() const { return length + 2 * border; }
  double carpetWidth() const { return width + 2 * border; }

  static FieldConfig loadYaml(const std::string& path);
  static FieldConfig parseYaml(const std::string& text, const std::string& source_name);
};

}  // namespace simswift
