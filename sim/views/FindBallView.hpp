// The FindBall view (the thesis's offnao FindBall tab, 4.2.4, Figure 4.8):
// a top-down image of the field with each segment of a ball distribution
// shaded from green (unlikely) to red (likely), each robot as a filled
// circle with a short heading line, its chosen search point as a ring, and
// an arrow from robot to point. Drawn with Cairo, written as PNG.
//
// Takes plain data (so it can draw one robot's view or the team's; the
// program side fills it: sim/programs/FindBallObserver.hpp); units
// mm and rad, field frame (origin at the centre spot, x toward the opponent
// goal, y left). Image: x to the right, field +y up.
#pragma once

#include <string>
#include <vector>

#include "common/field/FieldFacts.hpp"

namespace sim::views {

struct ViewRobot {
  int player = 0;
  double x = 0, y = 0, theta = 0;  // field mm, rad
  bool has_target = false;
  double target_x = 0, target_y = 0;  // chosen search point, field mm
  bool self = false;  // the robot whose view this is (drawn blue; teammates white)
};

struct FindBallViewData {
  // The field the robot believes in (its behaviour's, common/field/FieldFacts.hpp).
  double field_length = common::field::kLength;      // mm, between the lines
  double field_width = common::field::kWidth;        // mm
  double border = common::field::kBorderStripWidth;  // mm of carpet drawn round the lines
  // The distribution: columns x rows, row by row from the top-left (most
  // negative x, most positive y), as agent::behaviour::PositionalDistribution.
  int columns = 3, rows = 3;
  std::vector<double> probabilities;
  std::vector<ViewRobot> robots;
  std::string caption;  // drawn in the top-left corner (e.g. "t=12.3 s  team")
};

struct Rgb {
  double r = 0, g = 0, b = 0;  // 0..1
};

class FindBallView {
 public:
  explicit FindBallView(double px_per_mm = 0.08) : scale_(px_per_mm) {}

  int width(const FindBallViewData& d) const;   // px
  int height(const FindBallViewData& d) const;  // px
  // Field mm -> image px (x right, y down).
  void toPixel(const FindBallViewData& d, double fx, double fy, double* px, double* py) const;

  // Shade of a segment of probability p among J segments: green at 0,
  // yellow at the uniform 1/J, red from 2/J up (a fixed scale, so frames of
  // a video compare).
  static Rgb segmentColour(double p, int segments);
  static Rgb selfColour() { return {0.15, 0.35, 1.0}; }
  static Rgb teammateColour() { return {1.0, 1.0, 1.0}; }

  // Writes the PNG; false (and *error set) if the data are inconsistent or
  // the file cannot be written.
  bool writePng(const FindBallViewData& d, const std::string& path,
                std::string* error = nullptr) const;

 private:
  double scale_;  // px per mm
};

}  // namespace sim::views
