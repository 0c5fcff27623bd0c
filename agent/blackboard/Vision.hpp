// The vision adapter's output: the frame's detections as robot-relative
// measurements from the feet (as the thesis's adapter did), split into what
// each consumer needs. Written by the vision adapter, read by localisation,
// the ball tracker and behaviour.
// Units: mm, rad. Frame: robot-relative, origin between the feet on the
// ground, x forward, y left.
#pragma once

#include <cstdint>

namespace agent::blackboard {

// A point on the ground seen relative to the robot.
struct RRPoint {
  float x = 0, y = 0;       // mm
  float distance = 0;       // mm
  float heading = 0;        // rad, + = left
};

// Field features localisation can use. Point features are matched to the
// field model's landmarks of the same kind; LinePoint is a point somewhere on
// a painted line.
enum class FeatureKind : int32_t { GoalPost = 0, PenaltyCross, CentreCircle, Corner, LinePoint, NUM_KINDS };
const char* featureName(FeatureKind k);

// Corner shape when the detector tells it (L, T, X), else Unknown.
enum class CornerShape : int32_t { Unknown = 0, L = 1, T = 2, X = 3 };

struct FieldFeature {
  FeatureKind kind = FeatureKind::LinePoint;
  RRPoint where;
  int32_t camera = 0;  // 0 top, 1 bottom
  CornerShape shape = CornerShape::Unknown;  // corners only
};

struct SeenRobot {
  RRPoint where;
  int32_t team = -1;    // SPL team number seen, -1 unknown
  int32_t colour = -1;  // jersey: 0 blue, 1 red, -1 unknown
  bool fallen = false;  // lying on the ground
};

constexpr int kMaxFeatures = 48;
constexpr int kMaxSeenRobots = 10;

struct VisionMeasurements {
  int64_t frame_index = -1;
  double time = 0;             // s, frame time
  bool ball_seen = false;
  RRPoint ball;                // closest ball detection (mm)
  int32_t num_features = 0;
  FieldFeature features[kMaxFeatures];
  int32_t num_robots = 0;
  SeenRobot robots[kMaxSeenRobots];
};

inline const char* featureName(FeatureKind k) {
  switch (k) {
    case FeatureKind::GoalPost: return "goal post";
    case FeatureKind::PenaltyCross: return "penalty cross";
    case FeatureKind::CentreCircle: return "centre circle";
    case FeatureKind::Corner: return "corner";
    case FeatureKind::LinePoint: return "line point";
    default: return "?";
  }
}

}  // namespace agent::blackboard
