// PositionalDistribution (thesis 4.2.1): the field cut into J equal
// rectangular segments, each with the estimated probability that it holds
// the ball. Segments are numbered row by row from the top-left (most
// negative x, most positive y), so a 3 x 3 grid has table 4.1's centres:
// segment 1 at (-3000, 2000), 5 at (0, 0), 9 at (3000, -2000). Indices in
// code are 0-based (segment number = index + 1).
//
// Every mutating call normalises, so sum_j P(S_j) = 1 always holds for an
// observer (a sum that is zero or not finite resets to uniform).
#pragma once

#include <vector>

#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/behaviour/Geometry.hpp"
#include "common/field/FieldFacts.hpp"

namespace agent::behaviour {

class PositionalDistribution {
 public:
  // Uniform over a columns x rows grid over a length x width field (mm).
  PositionalDistribution(int columns = 3, int rows = 3, double length = common::field::kLength,
                         double width = common::field::kWidth);
  static PositionalDistribution fromConfig(const GridConfig& grid, const FieldGeometry& field);

  // The smallest grid whose segments' centre-to-corner distance is at most
  // max_half_diagonal (mm); ties go to the squarer segments. {columns, rows}.
  static std::pair<int, int> gridForDetection(double length, double width,
                                              double max_half_diagonal);

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  int size() const { return columns_ * rows_; }
  double length() const { return length_; }
  double width() const { return width_; }
  double segmentLength() const { return length_ / columns_; }  // mm along x
  double segmentWidth() const { return width_ / rows_; }       // mm along y

  double probability(int index) const { return p_[index]; }
  const std::vector<double>& probabilities() const { return p_; }
  Point2 centre(int index) const;  // field mm
  // The segment holding a field point; points off the field go to the
  // nearest segment; a non-finite point is in none (-1).
  int segmentAt(Point2 field) const;
  bool sameGrid(const PositionalDistribution& o) const {
    return columns_ == o.columns_ && rows_ == o.rows_;
  }

  // --- Updates; each normalises afterwards.
  void reset();                            // uniform
  void set(const std::vector<double>& w);  // weights >= 0 (size() of them)
  void add(int index, double amount);      // P_j += amount (index -1: no-op)
  void scale(int index, double factor);    // P_j *= factor (index -1: no-op)
  // P_j += alpha * (1/J - P_j) for all j (alpha in 0..1).
  void blendTowardUniform(double alpha);

 private:
  void normalise();

  int columns_, rows_;
  double length_, width_;
  std::vector<double> p_;
};

}  // namespace agent::behaviour
