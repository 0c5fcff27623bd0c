// The robot code's model of the SPL 2017 field for localisation: the
// dimensions of common/field/FieldFacts.hpp and the landmarks and lines they
// give. The simulator's field lives in fields/spl_2017.yaml;
// tests/world/test_field_model_agreement.cpp holds the two against each other.
//
// Field frame: origin at the centre spot, x toward the opponent goal, y left;
// mm. Lines are their centre lines.
#pragma once

#include <vector>

#include "agent/blackboard/Vision.hpp"
#include "common/field/FieldFacts.hpp"

namespace agent::localisation {

struct Vec2 {
  double x = 0, y = 0;  // mm
};

struct LineSegment {
  Vec2 a, b;  // mm
};

using blackboard::CornerShape;

struct Landmark {
  blackboard::FeatureKind kind;
  Vec2 at;  // mm, field frame
  CornerShape shape = CornerShape::Unknown;  // corners: L, T or X
};

struct FieldModel {
  double length = common::field::kLength, width = common::field::kWidth;  // mm, between the lines' centres
  double penalty_area_depth = common::field::kPenaltyAreaDepth, penalty_area_width = common::field::kPenaltyAreaWidth;  // mm
  double penalty_mark_distance = common::field::kPenaltyMarkDistance;     // mm, from the goal line
  double centre_circle_radius = common::field::kCentreCircleDiameter / 2;  // mm
  double goal_post_separation = common::field::kGoalPostSeparation;       // mm, between the posts' centres
  double line_width = common::field::kLineWidth;                          // mm

  // The SPL 2017 field.
  static FieldModel spl2017() { return FieldModel{}; }

  // Point landmarks (goal posts, crosses -- the penalty marks and the centre
  // mark --, centre circle centre, line corners L/T/X) and the straight
  // lines, derived from the dimensions.
  std::vector<Landmark> landmarks() const;
  std::vector<LineSegment> lines() const;
  double halfLength() const { return length / 2; }
  double halfWidth() const { return width / 2; }
};

// Distance (mm) from `p` to the nearest painted line (straight lines and the
// centre circle), for `lines` = field.lines() and the circle's radius.
double distanceToLines(const Vec2& p, const std::vector<LineSegment>& lines, double circle_radius);

// The same distance, prepared for the particle filter, which asks it per
// particle per line point (200 x 6 per frame): axis-parallel segments (all
// of the SPL field's) are kept as (fixed coordinate, low end, high end) and
// a segment is skipped once its perpendicular distance alone is no nearer
// than the best so far. distance(p) == distanceToLines(p, lines, r) exactly
// (the same operations on the same numbers; skipping never changes a min).
class FieldLines {
 public:
  FieldLines(const std::vector<LineSegment>& lines, double circle_radius);
  double distance(const Vec2& p) const;  // mm

 private:
  struct AxisSegment {
    double at, lo, hi;  // mm: the fixed coordinate, the other one's range
  };
  std::vector<AxisSegment> along_x_;  // y = at, x in [lo, hi]
  std::vector<AxisSegment> along_y_;  // x = at, y in [lo, hi]
  std::vector<LineSegment> slanted_;
  double circle_radius_;
};

}  // namespace agent::localisation
