// What a camera could see on the field, derived once from the FieldConfig:
// painted lines, their intersections (L, T, X) with an orientation, the
// centre circle, the marks and the goal posts. Immutable.
//
// Frame: field frame (origin at the centre spot, x toward the opponent
// goal, y left). Units: m, rad.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "common/libagent/CameraShared.hpp"
#include "sim/world/FieldConfig.hpp"

namespace simswift::vision {

struct FieldCorner {
  Eigen::Vector2d at;                  // m, field
  common::libagent::CornerKind kind;    // L, T or X
  double orientation;                  // rad, field (see Observation::orientation)
};

struct FieldPost {
  Eigen::Vector2d at;  // m, post axis on the ground
  double radius;       // m
  double height;       // m, ground to the top of the crossbar
};

struct FieldFeatures {
  std::vector<LineSegment> lines;      // m
  std::vector<LineCircle> circles;
  std::vector<Eigen::Vector2d> marks;  // cross centres (penalty marks and the centre mark), m
  std::vector<FieldCorner> corners;
  std::vector<FieldPost> posts;        // 4: own goal right, left, opponent goal right, left

  static FieldFeatures fromField(const FieldConfig& field);
};

}  // namespace simswift::vision
