#include "agent/localisation/FieldModel.hpp"

#include <algorithm>
#include <cmath>

namespace agent::localisation {

using blackboard::FeatureKind;
using blackboard::CornerShape;

std::vector<Landmark> FieldModel::landmarks() const {
  const double hx = halfLength(), hy = halfWidth();
  const double px = hx - penalty_area_depth, py = penalty_area_width / 2;
  std::vector<Landmark> l;
  for (double s : {-1.0, 1.0}) {
    // Goal posts on the goal line.
    l.push_back({FeatureKind::GoalPost, {s * hx, goal_post_separation / 2}});
    l.push_back({FeatureKind::GoalPost, {s * hx, -goal_post_separation / 2}});
    l.push_back({FeatureKind::PenaltyCross, {s * (hx - penalty_mark_distance), 0}});
    // Corners: field corners and penalty-area front corners are L; where the
    // penalty area meets the goal line and the halfway line meets the touch
    // lines, T; the centre circle crossing the halfway line, X.
    for (double t : {-1.0, 1.0}) {
      l.push_back({FeatureKind::Corner, {s * hx, t * hy}, CornerShape::L});
      l.push_back({FeatureKind::Corner, {s * px, t * py}, CornerShape::L});
      l.push_back({FeatureKind::Corner, {s * hx, t * py}, CornerShape::T});
    }
    l.push_back({FeatureKind::Corner, {0, s * hy}, CornerShape::T});
    l.push_back({FeatureKind::Corner, {0, s * centre_circle_radius}, CornerShape::X});
  }
  l.push_back({FeatureKind::CentreCircle, {0, 0}});
  // The centre mark is the same painted cross as the penalty marks, so a
  // cross detector reports it as one: without it here, a robot seeing only
  // the centre mark had no landmark to match it to but the penalty marks
  // 3.2 m away, and re-localisation put it there.
  l.push_back({FeatureKind::PenaltyCross, {0, 0}});
  return l;
}

std::vector<LineSegment> FieldModel::lines() const {
  const double hx = halfLength(), hy = halfWidth();
  const double px = hx - penalty_area_depth, py = penalty_area_width / 2;
  std::vector<LineSegment> v = {
      {{-hx, hy}, {hx, hy}},    // touch lines
      {{-hx, -hy}, {hx, -hy}},
      {{-hx, -hy}, {-hx, hy}},  // goal lines
      {{hx, -hy}, {hx, hy}},
      {{0, -hy}, {0, hy}},      // halfway line
  };
  for (double s : {-1.0, 1.0}) {
    v.push_back({{s * px, -py}, {s * px, py}});  // penalty area front
    v.push_back({{s * hx, py}, {s * px, py}});
    v.push_back({{s * hx, -py}, {s * px, -py}});
  }
  return v;
}

double distanceToLines(const Vec2& p, const std::vector<LineSegment>& lines, double circle_radius) {
  // Squared distances (no hypot in the loop: this runs per particle per line
  // point). Axis-parallel segments (all of the SPL field's) need no division.
  const double circle = std::sqrt(p.x * p.x + p.y * p.y) - circle_radius;
  double best2 = circle * circle;
  for (const LineSegment& s : lines) {
    double ex, ey;
    if (s.a.y == s.b.y) {
      ex = p.x - std::clamp(p.x, std::min(s.a.x, s.b.x), std::max(s.a.x, s.b.x));
      ey = p.y - s.a.y;
    } else if (s.a.x == s.b.x) {
      ex = p.x - s.a.x;
      ey = p.y - std::clamp(p.y, std::min(s.a.y, s.b.y), std::max(s.a.y, s.b.y));
    } else {
      const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
      const double t = std::clamp(((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      ex = p.x - (s.a.x + t * dx);
      ey = p.y - (s.a.y + t * dy);
    }
    best2 = std::min(best2, ex * ex + ey * ey);
  }
  return std::sqrt(best2);
}

FieldLines::FieldLines(const std::vector<LineSegment>& lines, double circle_radius)
    : circle_radius_(circle_radius) {
  for (const LineSegment& s : lines) {
    if (s.a.y == s.b.y) {
      along_x_.push_back({s.a.y, std::min(s.a.x, s.b.x), std::max(s.a.x, s.b.x)});
    } else if (s.a.x == s.b.x) {
      along_y_.push_back({s.a.x, std::min(s.a.y, s.b.y), std::max(s.a.y, s.b.y)});
    } else {
      slanted_.push_back(s);
    }
  }
}

double FieldLines::distance(const Vec2& p) const {
  const double circle = std::sqrt(p.x * p.x + p.y * p.y) - circle_radius_;
  double best2 = circle * circle;
  // fl(ex^2 + ey^2) >= fl(ey^2): a segment whose perpendicular part alone
  // is no nearer cannot lower the minimum.
  for (const AxisSegment& s : along_x_) {
    const double ey = p.y - s.at, ey2 = ey * ey;
    if (ey2 >= best2) continue;
    const double ex = p.x - std::clamp(p.x, s.lo, s.hi);
    best2 = std::min(best2, ex * ex + ey2);
  }
  for (const AxisSegment& s : along_y_) {
    const double ex = p.x - s.at, ex2 = ex * ex;
    if (ex2 >= best2) continue;
    const double ey = p.y - std::clamp(p.y, s.lo, s.hi);
    best2 = std::min(best2, ex2 + ey * ey);
  }
  for (const LineSegment& s : slanted_) {
    const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    const double t = std::clamp(((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    const double ex = p.x - (s.a.x + t * dx), ey = p.y - (s.a.y + t * dy);
    best2 = std::min(best2, ex * ex + ey * ey);
  }
  return std::sqrt(best2);
}

}  // namespace agent::localisation
