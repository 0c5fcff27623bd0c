// Foot force-sensitive resistors: 4 per foot, placed as on the NAO V5
// (Aldebaran's NAO V5 (H25) documentation), each saturating at 25 N. Pure logic: the caller
// supplies contact points and normal forces in the foot (ankle) frame.
//
// Model: each contact's normal force is shared among the four sensors with
// the bilinear weights of its point inside the sensor quadrilateral (inverse
// bilinear map, clamped to the quadrilateral's edges). The weights sum to 1,
// so the four values sum to the foot's normal force until a sensor
// saturates, and the weighted mean of the sensor positions (the CoP the
// robot computes) equals the true centre of pressure whenever it lies inside
// the quadrilateral.
#pragma once

#include <Eigen/Core>
#include <array>

namespace simswift::sensors {

enum FsrIndex : int { FrontLeft = 0, FrontRight = 1, RearLeft = 2, RearRight = 3 };

struct FsrLayout {
  // Sensor positions (m) in the ankle frame, x forward, y left, indexed by
  // FsrIndex. The sole is at z = -0.04511 m.
  std::array<Eigen::Vector2d, 4> sensor;

  static FsrLayout left();
  static FsrLayout right();  // the left foot mirrored in y
};

// Bilinear weights (sum 1, each >= 0) of a force at `point` (m, ankle frame).
std::array<double, 4> fsrWeights(const FsrLayout& layout, const Eigen::Vector2d& point);

// Adds a contact's normal force `fz` (N, >= 0 counts) at `point` to `forces`.
void distributeForce(const FsrLayout& layout, const Eigen::Vector2d& point, double fz,
                     std::array<double, 4>& forces);

// Clamps each value to 0..max (N).
void saturate(std::array<double, 4>& forces, double max);

// Force-weighted mean of the sensor positions (m, ankle frame); (0, 0) when
// the total is below `unloaded` (N).
Eigen::Vector2d centreOfPressure(const FsrLayout& layout, const std::array<double, 4>& forces,
                                 double unloaded);

}  // namespace simswift::sensors
