#include "sim/sensors/Fsr.hpp"

#include <algorithm>
#include <cmath>

#include "common/nao/NaoFacts.hpp"

namespace simswift::sensors {

FsrLayout FsrLayout::left() {
  // NAO V5 left foot in the ankle frame: the NAO's hardware facts
  // (common/nao/NaoFacts.hpp, mm) in m. The sensors do not form an exact
  // rectangle, hence the inverse bilinear map below.
  FsrLayout l;
  for (int i = 0; i < 4; ++i) {
    const common::nao::Point2 p = common::nao::fsrPosition(common::nao::Side::Left, static_cast<common::nao::Fsr>(i));
    l.sensor[i] = {p.x * 1e-3, p.y * 1e-3};
  }
  return l;
}

FsrLayout FsrLayout::right() {
  // Mirroring swaps the sides: the right foot's front-left sensor is the
  // mirror image of the left foot's front-right one.
  const FsrLayout l = left();
  auto mirror = [](const Eigen::Vector2d& p) { return Eigen::Vector2d(p.x(), -p.y()); };
  FsrLayout r;
  r.sensor[FrontLeft] = mirror(l.sensor[FrontRight]);
  r.sensor[FrontRight] = mirror(l.sensor[FrontLeft]);
  r.sensor[RearLeft] = mirror(l.sensor[RearRight]);
  r.sensor[RearRight] = mirror(l.sensor[RearLeft]);
  return r;
}

std::array<double, 4> fsrWeights(const FsrLayout& layout, const Eigen::Vector2d& point) {
  const Eigen::Vector2d& fl = layout.sensor[FrontLeft];
  const Eigen::Vector2d& fr = layout.sensor[FrontRight];
  const Eigen::Vector2d& rl = layout.sensor[RearLeft];
  const Eigen::Vector2d& rr = layout.sensor[RearRight];
  // P(u, v) = (1-u)(1-v) rr + u(1-v) fr + (1-u)v rl + uv fl, u rear->front,
  // v right->left. Newton's method from the centre; the quadrilateral is
  // nearly a rectangle so a few iterations converge to machine precision.
  double u = 0.5, v = 0.5;
  for (int it = 0; it < 12; ++it) {
    const Eigen::Vector2d p =
        (1 - u) * (1 - v) * rr + u * (1 - v) * fr + (1 - u) * v * rl + u * v * fl;
    const Eigen::Vector2d du = (1 - v) * (fr - rr) + v * (fl - rl);
    const Eigen::Vector2d dv = (1 - u) * (rl - rr) + u * (fl - fr);
    const double det = du.x() * dv.y() - du.y() * dv.x();
    if (std::abs(det) < 1e-12) break;
    const Eigen::Vector2d r = point - p;
    const double u1 = u + (r.x() * dv.y() - r.y() * dv.x()) / det;
    const double v1 = v + (du.x() * r.y() - du.y() * r.x()) / det;
    // At a fixed point every further iteration repeats this one: stopping
    // there changes nothing (usually after 3-4 of the 12).
    if (u1 == u && v1 == v) break;
    u = u1;
    v = v1;
  }
  if (!std::isfinite(u) || !std::isfinite(v)) u = v = 0.5;
  // A point outside the sensors loads the nearest edge (clamped weights).
  u = std::clamp(u, 0.0, 1.0);
  v = std::clamp(v, 0.0, 1.0);
  std::array<double, 4> w;
  w[FrontLeft] = u * v;
  w[FrontRight] = u * (1 - v);
  w[RearLeft] = (1 - u) * v;
  w[RearRight] = (1 - u) * (1 - v);
  return w;
}

void distributeForce(const FsrLayout& layout, const Eigen::Vector2d& point, double fz,
                     std::array<double, 4>& forces) {
  if (!(fz > 0)) return;  // a sole cannot be pulled
  const std::array<double, 4> w = fsrWeights(layout, point);
  for (int i = 0; i < 4; ++i) forces[i] += w[i] * fz;
}

void saturate(std::array<double, 4>& forces, double max) {
  for (double& f : forces) f = std::clamp(f, 0.0, max);
}

Eigen::Vector2d centreOfPressure(const FsrLayout& layout, const std::array<double, 4>& forces,
                                 double unloaded) {
  double total = 0;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int i = 0; i < 4; ++i) {
    total += forces[i];
    sum += forces[i] * layout.sensor[i];
  }
  if (total < unloaded || total <= 0) return Eigen::Vector2d::Zero();
  return sum / total;
}

}  // namespace simswift::sensors
