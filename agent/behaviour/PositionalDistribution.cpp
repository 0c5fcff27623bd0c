#include "agent/behaviour/PositionalDistribution.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace agent::behaviour {

PositionalDistribution::PositionalDistribution(int columns, int rows, double length,
                                               double width)
    : columns_(columns), rows_(rows), length_(length), width_(width) {
  if (columns < 1 || rows < 1 || !(length > 0) || !(width > 0))
    throw std::invalid_argument("PositionalDistribution: grid and field sizes must be positive");
  p_.assign(static_cast<size_t>(columns * rows), 1.0 / (columns * rows));
}

PositionalDistribution PositionalDistribution::fromConfig(const GridConfig& grid,
                                                          const FieldGeometry& field) {
  if (!grid.derive_from_detection)
    return PositionalDistribution(grid.columns, grid.rows, field.length, field.width);
  auto [c, r] = gridForDetection(field.length, field.width,
                                 grid.reliable_detection_distance - grid.detection_margin);
  return PositionalDistribution(c, r, field.length, field.width);
}

std::pair<int, int> PositionalDistribution::gridForDetection(double length, double width,
                                                             double max_half_diagonal) {
  constexpr int kMax = 30;  // per side; beyond it the payload would not fit anyway
  int best_c = kMax, best_r = kMax;
  double best_skew = 1e18;
  for (int c = 1; c <= kMax; ++c) {
    for (int r = 1; r <= kMax; ++r) {
      const double sl = length / c, sw = width / r;
      if (std::hypot(sl / 2, sw / 2) > max_half_diagonal) continue;
      const double skew = std::abs(sl - sw);
      if (c * r < best_c * best_r || (c * r == best_c * best_r && skew < best_skew)) {
        best_c = c;
        best_r = r;
        best_skew = skew;
      }
    }
  }
  return {best_c, best_r};
}

Point2 PositionalDistribution::centre(int index) const {
  const int row = index / columns_, col = index % columns_;
  return {-length_ / 2 + (col + 0.5) * segmentLength(), width_ / 2 - (row + 0.5) * segmentWidth()};
}

int PositionalDistribution::segmentAt(Point2 f) const {
  if (!std::isfinite(f.x) || !std::isfinite(f.y)) return -1;
  int col = static_cast<int>(std::floor((f.x + length_ / 2) / segmentLength()));
  int row = static_cast<int>(std::floor((width_ / 2 - f.y) / segmentWidth()));
  col = std::clamp(col, 0, columns_ - 1);
  row = std::clamp(row, 0, rows_ - 1);
  return row * columns_ + col;
}

void PositionalDistribution::reset() { std::fill(p_.begin(), p_.end(), 1.0 / size()); }

void PositionalDistribution::set(const std::vector<double>& w) {
  if (static_cast<int>(w.size()) != size())
    throw std::invalid_argument("PositionalDistribution::set: wrong number of segments");
  for (size_t j = 0; j < p_.size(); ++j) p_[j] = std::max(0.0, w[j]);
  normalise();
}

void PositionalDistribution::add(int index, double amount) {
  if (index < 0 || index >= size() || !std::isfinite(amount)) return;
  p_[index] = std::max(0.0, p_[index] + amount);
  normalise();
}

void PositionalDistribution::scale(int index, double factor) {
  if (index < 0 || index >= size() || !std::isfinite(factor)) return;
  p_[index] *= std::max(0.0, factor);
  normalise();
}

void PositionalDistribution::blendTowardUniform(double alpha) {
  alpha = std::clamp(alpha, 0.0, 1.0);
  const double u = 1.0 / size();
  for (double& p : p_) p += alpha * (u - p);
  normalise();
}

void PositionalDistribution::normalise() {
  double sum = 0;
  for (double p : p_) sum += p;
  if (!(sum > 0) || !std::isfinite(sum)) {
    reset();
    return;
  }
  for (double& p : p_) p /= sum;
}

}  // namespace agent::behaviour
