#include "sim/views/FindBallView.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/nao/NaoFacts.hpp"

namespace sim::views {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRobotRadius = common::nao::kFootprintRadius;  // mm, drawn size of a robot
constexpr double kTargetRadius = 120.0;  // mm, drawn size of a search point

void setColour(cairo_t* cr, Rgb c) { cairo_set_source_rgb(cr, c.r, c.g, c.b); }

// An arrow from (x0, y0) to (x1, y1) in px, head size h px.
void arrow(cairo_t* cr, double x0, double y0, double x1, double y1, double h) {
  const double a = std::atan2(y1 - y0, x1 - x0);
  cairo_move_to(cr, x0, y0);
  cairo_line_to(cr, x1, y1);
  cairo_stroke(cr);
  cairo_move_to(cr, x1, y1);
  cairo_line_to(cr, x1 - h * std::cos(a - 0.4), y1 - h * std::sin(a - 0.4));
  cairo_line_to(cr, x1 - h * std::cos(a + 0.4), y1 - h * std::sin(a + 0.4));
  cairo_close_path(cr);
  cairo_fill(cr);
}

}  // namespace

int FindBallView::width(const FindBallViewData& d) const {
  return static_cast<int>(std::lround((d.field_length + 2 * d.border) * scale_));
}
int FindBallView::height(const FindBallViewData& d) const {
  return static_cast<int>(std::lround((d.field_width + 2 * d.border) * scale_));
}

void FindBallView::toPixel(const FindBallViewData& d, double fx, double fy, double* px,
                           double* py) const {
  *px = (fx + d.field_length / 2 + d.border) * scale_;
  *py = (d.field_width / 2 + d.border - fy) * scale_;
}

Rgb FindBallView::segmentColour(double p, int segments) {
  const double t = std::clamp(p * std::max(1, segments) / 2.0, 0.0, 1.0);  // 0.5 = uniform
  const Rgb green{0.0, 0.75, 0.0}, yellow{0.9, 0.75, 0.0}, red{0.9, 0.0, 0.0};
  const Rgb& a = t < 0.5 ? green : yellow;
  const Rgb& b = t < 0.5 ? yellow : red;
  const double u = t < 0.5 ? 2 * t : 2 * t - 1;
  return {a.r + (b.r - a.r) * u, a.g + (b.g - a.g) * u, a.b + (b.b - a.b) * u};
}

bool FindBallView::writePng(const FindBallViewData& d, const std::string& path,
                            std::string* error) const {
  auto fail = [&](const std::string& why) {
    if (error) *error = why;
    return false;
  };
  if (!(d.field_length > 0) || !(d.field_width > 0) || d.border < 0 || !(scale_ > 0))
    return fail("FindBallView: field size and scale must be positive");
  const int segments = d.columns * d.rows;
  if (d.columns < 1 || d.rows < 1 || static_cast<int>(d.probabilities.size()) != segments)
    return fail("FindBallView: probabilities do not match the " + std::to_string(d.columns) +
                " x " + std::to_string(d.rows) + " grid");

  cairo_surface_t* surface =
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, width(d), height(d));
  cairo_t* cr = cairo_create(surface);
  double x0, y0, x1, y1;

  // Carpet.
  cairo_set_source_rgb(cr, 0.1, 0.35, 0.1);
  cairo_paint(cr);

  // Segments, opaque, exactly covering the field inside the lines.
  const double sl = d.field_length / d.columns, sw = d.field_width / d.rows;
  for (int j = 0; j < segments; ++j) {
    const int row = j / d.columns, col = j % d.columns;
    toPixel(d, -d.field_length / 2 + col * sl, d.field_width / 2 - row * sw, &x0, &y0);
    toPixel(d, -d.field_length / 2 + (col + 1) * sl, d.field_width / 2 - (row + 1) * sw, &x1, &y1);
    cairo_rectangle(cr, x0, y0, x1 - x0, y1 - y0);
    setColour(cr, segmentColour(d.probabilities[j], segments));
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.0);
    cairo_stroke(cr);
  }

  // Field lines (white, 50 mm): outline, halfway line, centre circle, penalty areas.
  cairo_set_source_rgba(cr, 1, 1, 1, 0.8);
  cairo_set_line_width(cr, std::max(1.0, common::field::kLineWidth * scale_));
  toPixel(d, -d.field_length / 2, d.field_width / 2, &x0, &y0);
  cairo_rectangle(cr, x0, y0, d.field_length * scale_, d.field_width * scale_);
  toPixel(d, 0, d.field_width / 2, &x0, &y0);
  toPixel(d, 0, -d.field_width / 2, &x1, &y1);
  cairo_move_to(cr, x0, y0);
  cairo_line_to(cr, x1, y1);
  cairo_stroke(cr);
  toPixel(d, 0, 0, &x0, &y0);
  cairo_arc(cr, x0, y0, common::field::kCentreCircleDiameter / 2 * scale_, 0, 2 * kPi);
  cairo_stroke(cr);
  for (double side : {-1.0, 1.0}) {
    const double half_area = common::field::kPenaltyAreaWidth / 2;  // mm
    toPixel(d, side * d.field_length / 2, half_area, &x0, &y0);
    toPixel(d, side * (d.field_length / 2 - common::field::kPenaltyAreaDepth), -half_area, &x1, &y1);
    cairo_rectangle(cr, std::min(x0, x1), y0, std::abs(x1 - x0), y1 - y0);
    cairo_stroke(cr);
  }

  // Robots, their points, arrows between them.
  cairo_set_line_width(cr, std::max(1.5, 30 * scale_));
  for (const ViewRobot& r : d.robots) {
    const Rgb c = r.self ? selfColour() : teammateColour();
    double rx, ry;
    toPixel(d, r.x, r.y, &rx, &ry);
    if (r.has_target) {
      double tx, ty;
      toPixel(d, r.target_x, r.target_y, &tx, &ty);
      setColour(cr, c);
      const double len = std::hypot(tx - rx, ty - ry);
      const double gap = (kRobotRadius + kTargetRadius) * scale_;
      if (len > gap) {  // arrow from the robot's rim to the point's rim
        const double ux = (tx - rx) / len, uy = (ty - ry) / len;
        arrow(cr, rx + ux * kRobotRadius * scale_, ry + uy * kRobotRadius * scale_,
              tx - ux * kTargetRadius * scale_, ty - uy * kTargetRadius * scale_,
              std::max(4.0, 150 * scale_));
      }
      cairo_arc(cr, tx, ty, kTargetRadius * scale_, 0, 2 * kPi);
      cairo_stroke(cr);
    }
    cairo_arc(cr, rx, ry, kRobotRadius * scale_, 0, 2 * kPi);
    setColour(cr, c);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_stroke(cr);
    // Heading: a black line from the centre to the rim.
    cairo_move_to(cr, rx, ry);
    cairo_line_to(cr, rx + kRobotRadius * scale_ * std::cos(r.theta),
                  ry - kRobotRadius * scale_ * std::sin(r.theta));
    cairo_stroke(cr);
    // Player number beside it.
    cairo_set_font_size(cr, std::max(8.0, 220 * scale_));
    cairo_move_to(cr, rx + kRobotRadius * scale_ * 1.2, ry - kRobotRadius * scale_ * 1.2);
    setColour(cr, c);
    cairo_show_text(cr, std::to_string(r.player).c_str());
  }

  if (!d.caption.empty()) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_set_font_size(cr, std::max(8.0, 250 * scale_));
    cairo_move_to(cr, 5, std::max(10.0, 300 * scale_));
    cairo_show_text(cr, d.caption.c_str());
  }

  cairo_destroy(cr);
  const cairo_status_t st = cairo_surface_write_to_png(surface, path.c_str());
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS)
    return fail("FindBallView: cannot write " + path + ": " + cairo_status_to_string(st));
  return true;
}

}  // namespace sim::views
