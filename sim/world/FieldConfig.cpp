// Field configuration: SPL 2017 defaults and the YAML loader.
//
// YAML layout (all optional except where noted; units m, kg):
//   field:                      (required)
//     length, width, border, line_width
//     lines:   [{name, from: [x, y], to: [x, y], width}]   from/to required
//     circles: [{name, centre: [x, y], radius, width}]     centre/radius required
//     crosses: [{name, at: [x, y], size, width}]           at required
//     goal:    {post_diameter, post_height, inner_width, depth, net_height,
//               net_stiffness, net_damping}
//     ball:    {diameter, mass, rolling_friction, restitution,
//               ground_restitution, linear_damping}
//     surface: {friction, ball_friction, other_friction, soft_erp, soft_cfm}
// A markings list given in the file replaces the default SPL markings.
#include <cmath>

#include "sim/world/FieldConfig.hpp"
#include "sim/world/ConfigError.hpp"

namespace simswift {

FieldConfig FieldConfig::spl2017() {
  FieldConfig f;
  f.setSplMarkings();
  return f;
}

void FieldConfig::setSplMarkings() {
  // Positions are line centres, field frame (m). SPL 2017: penalty area
  // 0.6 m deep x 2.2 m wide, penalty mark 1.3 m from the goal line, centre
  // circle 1.5 m diameter, crosses 0.1 m across.
  const double hx = length / 2, hy = width / 2, w = line_width;
  const double pa_depth = 0.6, pa_half_width = 1.1, mark = 1.3;
  lines.clear();
  circles.clear();
  crosses.clear();
  auto seg = [&](double ax, double ay, double bx, double by) {
    lines.push_back({ax, ay, bx, by, w});
  };
  seg(-hx, hy, hx, hy);    // left touch line
  seg(-hx, -hy, hx, -hy);  // right touch line
  seg(-hx, -hy, -hx, hy);  // own goal line
  seg(hx, -hy, hx, hy);    // opponent goal line
  seg(0, -hy, 0, hy);      // halfway line
  for (double s : {-1.0, 1.0}) {
    const double front = s * (hx - pa_depth);
    seg(front, -pa_half_width, front, pa_half_width);      // penalty area front
    seg(s * hx, pa_half_width, front, pa_half_width);      // its left side
    seg(s * hx, -pa_half_width, front, -pa_half_width);    // its right side
  }
  circles.push_back({0, 0, 0.75, w});
  crosses.push_back({-(hx - mark), 0, 0.1, w});
  crosses.push_back({0, 0, 0.1, w});
  crosses.push_back({hx - mark, 0, 0.1, w});
}

namespace {

void checkOnCarpet(const YamlReader& r, const std::string& key, const FieldConfig& f, double x,
                   double y) {
  if (std::fabs(x) > f.carpetLength() / 2 + 1e-9 || std::fabs(y) > f.carpetWidth() / 2 + 1e-9) {
    r.fail(key, "point (" + std::to_string(x) + ", " + std::to_string(y) +
                    ") is off the carpet");
  }
}

FieldConfig parse(const YAML::Node& root, const std::string& source) {
  FieldConfig f;
  f.source = source;
  YamlReader top(root, source);
  YamlReader r = top.map("field");
  top.finish();

  // Sane ranges (m, kg, SI): anything a real field could be, nothing that
  // overflows ODE or makes the geometry meaningless.
  f.length = r.number("length", f.length, Range::closed(1, 50));
  f.width = r.number("width", f.width, Range::closed(1, 50));
  if (f.width > f.length) r.fail("width", "must not exceed length (" + std::to_string(f.length) + " m)");
  f.border = r.number("border", f.border, Range::closed(0, 10));
  f.line_width = r.number("line_width", f.line_width, Range::openClosed(0, 0.5));
  f.setSplMarkings();  // defaults, scaled to the dimensions read so far

  const Range pos = Range::openClosed(0, 1);  // line widths, cross sizes (m)
  if (r.has("lines")) {
    f.lines.clear();
    for (const YamlReader& l : r.list("lines")) {
      l.string("name", "");
      auto a = l.numbers("from", 2), b = l.numbers("to", 2);
      checkOnCarpet(l, "from", f, a[0], a[1]);
      checkOnCarpet(l, "to", f, b[0], b[1]);
      f.lines.push_back({a[0], a[1], b[0], b[1], l.number("width", f.line_width, pos)});
      l.finish();
    }
  }
  if (r.has("circles")) {
    f.circles.clear();
    for (const YamlReader& c : r.list("circles")) {
      c.string("name", "");
      auto ctr = c.numbers("centre", 2);
      checkOnCarpet(c, "centre", f, ctr[0], ctr[1]);
      f.circles.push_back({ctr[0], ctr[1], c.number("radius", Range::openClosed(0, 25)),
                           c.number("width", f.line_width, pos)});
      c.finish();
    }
  }
  if (r.has("crosses")) {
    f.crosses.clear();
    for (const YamlReader& c : r.list("crosses")) {
      c.string("name", "");
      auto at = c.numbers("at", 2);
      checkOnCarpet(c, "at", f, at[0], at[1]);
      f.crosses.push_back({at[0], at[1], c.number("size", 0.1, pos),
                           c.number("width", f.line_width, pos)});
      c.finish();
    }
  }

  if (auto g = r.optionalMap("goal")) {
    GoalConfig& o = f.goal;
    o.post_diameter = g->number("post_diameter", o.post_diameter, Range::openClosed(0, 1));
    o.post_height = g->number("post_height", o.post_height, Range::openClosed(0, 5));
    o.inner_width = g->number("inner_width", o.inner_width, Range::openClosed(0, 20));
    o.depth = g->number("depth", o.depth, Range::openClosed(0, 5));
    o.net_height = g->number("net_height", o.net_height, Range::openClosed(0, 5));
    o.net_stiffness = g->number("net_stiffness", o.net_stiffness, Range::openClosed(0, 1e6));
    o.net_damping = g->number("net_damping", o.net_damping, Range::closed(0, 1e5));
    // The goal as a whole (FieldGeometry.cpp): posts are capsules whose
    // straight part is post_height - post_diameter, so the crossbar must
    // stand above a whole post diameter; the net hangs inside the posts;
    // the goal fits between the touch lines.
    if (!(o.post_height > 2 * o.post_diameter))
      g->fail("post_height", "must exceed twice post_diameter (" + std::to_string(o.post_diameter) +
                                 " m): the posts are capsules (got " + std::to_string(o.post_height) + ")");
    if (o.net_height > o.post_height)
      g->fail("net_height", "must not exceed post_height (" + std::to_string(o.post_height) + " m)");
    if (o.inner_width + 2 * o.post_diameter > f.width)
      g->fail("inner_width", "the goal (inner_width + 2 post_diameter) is wider than the field (" +
                                 std::to_string(f.width) + " m)");
    g->finish();
  }
  if (auto b = r.optionalMap("ball")) {
    BallConfig& o = f.ball;
    o.diameter = b->number("diameter", o.diameter, Range::closed(0.01, 1));
    o.mass = b->number("mass", o.mass, Range::closed(0.001, 10));
    o.rolling_friction = b->number("rolling_friction", o.rolling_friction, Range::closed(0, 10));
    o.restitution = b->number("restitution", o.restitution, Range::closed(0, 1));
    o.ground_restitution =
        b->number("ground_restitution", o.ground_restitution, Range::closed(0, 1));
    o.linear_damping = b->number("linear_damping", o.linear_damping, Range::closed(0, 100));
    b->finish();
  }
  if (auto s = r.optionalMap("surface")) {
    SurfaceConfig& o = f.surface;
    o.friction = s->number("friction", o.friction, Range::closed(0, 10));
    o.ball_friction = s->number("ball_friction", o.ball_friction, Range::closed(0, 10));
    o.other_friction = s->number("other_friction", o.other_friction, Range::closed(0, 10));
    o.soft_erp = s->number("soft_erp", o.soft_erp, Range::closed(0, 1));
    o.soft_cfm = s->number("soft_cfm", o.soft_cfm, Range::closed(0, 1));
    s->finish();
  }
  r.finish();
  return f;
}

}  // namespace

FieldConfig FieldConfig::loadYaml(const std::string& path) {
  return parse(YamlReader::parseFile(path), path);
}

FieldConfig FieldConfig::parseYaml(const std::string& text, const std::string& source_name) {
  return parse(YamlReader::parse(text, source_name), source_name);
}

}  // namespace simswift
