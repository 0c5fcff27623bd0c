// The SPL field as typed configuration, loaded from YAML (fields/*.yaml).
// Every struct has defaults equal to the SPL 2017 rules, so a YAML file only
// needs what it changes; an unknown key, a missing required field or a bad
// value throws ConfigError naming the file, line and key.
//
// Frame: field frame, origin at the centre spot, x toward the opponent
// (positive) goal, y left, z up. Units: m, kg, rad.
#pragma once

#include <string>
#include <vector>

#include "sim/world/ConfigError.hpp"

namespace simswift {

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
  // The net as a damped spring (so a shot is absorbed, not bounced back):
  // stiffness N/m and damping N*s/m per contact.
  double net_stiffness = 300.0;
  double net_damping = 8.0;
};

struct BallConfig {
  double diameter = 0.10;
  double mass = 0.044;
  // Rolling-resistance coefficient on carpet (dimensionless: resisting force
  // / normal force). 0.07 decelerates a rolling ball by ~0.5 m/s^2; a ball
  // struck at 2.5 m/s first slides (losing 2/7 of its speed) and then rolls,
  // stopping after ~3.5 m, as on SPL carpet.
  double rolling_friction = 0.07;
  double restitution = 0.6;         // against posts and robots
  double ground_restitution = 0.3;  // dropped on the carpet
  double linear_damping = 0.0;      // extra air drag (1/s)
};

struct SurfaceConfig {
  double friction = 0.8;            // foot-carpet Coulomb coefficient
  double ball_friction = 0.5;       // ball-carpet
  double other_friction = 0.5;      // every other pair (robot-robot, ball-post, ball-robot...)
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

  // The SPL 2017 field with all its markings (what an empty YAML gives).
  static FieldConfig spl2017();
  // Replaces lines/circles/crosses with the SPL 2017 markings for the
  // current length/width/line_width (penalty area 0.6 x 2.2 m, marks 1.3 m
  // from the goal lines, centre circle 0.75 m radius).
  void setSplMarkings();

  // A YAML file's markings lists, when present, replace the defaults.
  static FieldConfig loadYaml(const std::string& path);
  static FieldConfig parseYaml(const std::string& text, const std::string& source_name);
};

}  // namespace simswift
