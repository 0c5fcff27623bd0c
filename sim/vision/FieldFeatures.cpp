#include "sim/vision/FieldFeatures.hpp"

#include <cmath>

namespace simswift::vision {

namespace al = common::libagent;

namespace {

constexpr double kTol = 0.01;  // m: line ends closer than this meet

double angleOf(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }

// Where along segment s (0 at a, 1 at b) the point p lies, and whether p is
// at one of its ends (within kTol).
struct OnSegment {
  bool end;
  Eigen::Vector2d far;  // the end of s farther from p
};
OnSegment classify(const LineSegment& s, const Eigen::Vector2d& p) {
  const Eigen::Vector2d a(s.ax, s.ay), b(s.bx, s.by);
  const bool end = (p - a).norm() < kTol || (p - b).norm() < kTol;
  return {end, (p - a).norm() > (p - b).norm() ? a : b};
}

void addCorner(std::vector<FieldCorner>& out, const FieldCorner& c) {
  for (const FieldCorner& o : out)
    if ((o.at - c.at).norm() < kTol) return;  // three lines through one point: keep the first
  out.push_back(c);
}

}  // namespace

FieldFeatures FieldFeatures::fromField(const FieldConfig& field) {
  FieldFeatures f;
  f.lines = field.lines;
  f.circles = field.circles;
  for (const LineCross& c : field.crosses) f.marks.emplace_back(c.x, c.y);

  const double r = field.goal.post_diameter / 2;
  const double post_y = field.goal.inner_width / 2 + r;  // post axis |y|
  for (double s : {-1.0, 1.0})
    for (double side : {-1.0, 1.0}) f.posts.push_back({{s * field.length / 2, side * post_y}, r, field.goal.post_height});

  // Line-line intersections.
  for (size_t i = 0; i < f.lines.size(); ++i) {
    for (size_t j = i + 1; j < f.lines.size(); ++j) {
      const LineSegment& s1 = f.lines[i];
      const LineSegment& s2 = f.lines[j];
      const Eigen::Vector2d a1(s1.ax, s1.ay), d1(s1.bx - s1.ax, s1.by - s1.ay);
      const Eigen::Vector2d a2(s2.ax, s2.ay), d2(s2.bx - s2.ax, s2.by - s2.ay);
      const double den = d1.x() * d2.y() - d1.y() * d2.x();
      if (std::abs(den) < 1e-9 * d1.norm() * d2.norm()) continue;  // parallel
      const Eigen::Vector2d w = a2 - a1;
      const double t = (w.x() * d2.y() - w.y() * d2.x()) / den;
      const double u = (w.x() * d1.y() - w.y() * d1.x()) / den;
      const double e1 = kTol / d1.norm(), e2 = kTol / d2.norm();
      if (t < -e1 || t > 1 + e1 || u < -e2 || u > 1 + e2) continue;
      const Eigen::Vector2d p = a1 + t * d1;
      const OnSegment c1 = classify(s1, p), c2 = classify(s2, p);
      FieldCorner c{p, al::CornerKind::X, angleOf(d1)};
      if (c1.end && c2.end) {
        c.kind = al::CornerKind::L;
        c.orientation = angleOf((c1.far - p).normalized() + (c2.far - p).normalized());
      } else if (c1.end || c2.end) {
        c.kind = al::CornerKind::T;
        c.orientation = angleOf((c1.end ? c1.far : c2.far) - p);  // along the stem
      }
      addCorner(f.corners, c);
    }
  }
  // Lines crossing a circle (the halfway line through the centre circle).
  for (const LineCircle& ci : f.circles) {
    const Eigen::Vector2d cc(ci.cx, ci.cy);
    for (const LineSegment& s : f.lines) {
      const Eigen::Vector2d a(s.ax, s.ay), d(s.bx - s.ax, s.by - s.ay);
      const Eigen::Vector2d m = a - cc;
      const double A = d.dot(d), B = 2 * m.dot(d), C = m.dot(m) - ci.radius * ci.radius;
      const double disc = B * B - 4 * A * C;
      if (disc <= 0) continue;  // misses, or only touches
      for (double sgn : {-1.0, 1.0}) {
        const double t = (-B + sgn * std::sqrt(disc)) / (2 * A);
        if (t <= 0 || t >= 1) continue;
        addCorner(f.corners, {a + t * d, al::CornerKind::X, angleOf(d)});
      }
    }
  }
  return f;
}

}  // namespace simswift::vision
