#include "agent/perception/VisionAdapter.hpp"

#include <algorithm>
#include <cmath>

namespace agent::perception {

using blackboard::FeatureKind;
using libagent::ObservationType;

namespace {
// Completes a detection: x, y from distance/heading when only those are set.
bool toPoint(const libagent::Observation& o, double max_distance, blackboard::RRPoint& p) {
  double x = o.x, y = o.y;
  if (x == 0 && y == 0 && o.distance > 0) {
    x = o.distance * std::cos(o.heading);
    y = o.distance * std::sin(o.heading);
  }
  if (!std::isfinite(x) || !std::isfinite(y)) return false;
  const double d = std::hypot(x, y);
  if (d > max_distance) return false;
  p.x = static_cast<float>(x);
  p.y = static_cast<float>(y);
  p.distance = static_cast<float>(d);
  p.heading = static_cast<float>(std::atan2(y, x));
  return true;
}
}  // namespace

blackboard::VisionMeasurements adaptVision(const blackboard::FrameInfo& frame, bool fallen,
                                           const VisionAdapterConfig& cfg) {
  blackboard::VisionMeasurements v;
  v.frame_index = frame.frame_index;
  v.time = frame.time;
  if (fallen) return v;
  const int n = std::min<int>(frame.num_observations, libagent::kMaxObservations);
  for (int i = 0; i < n; ++i) {
    const libagent::Observation& o = frame.observations[i];
    blackboard::RRPoint p;
    if (!toPoint(o, cfg.max_distance, p)) continue;
    FeatureKind kind;
    switch (o.type) {
      case ObservationType::Ball:
        if (!v.ball_seen || p.distance < v.ball.distance) v.ball = p;
        v.ball_seen = true;
        continue;
      case ObservationType::Robot:
        if (v.num_robots < blackboard::kMaxSeenRobots) v.robots[v.num_robots++] = {p, o.team};
        continue;
      case ObservationType::GoalPost: kind = FeatureKind::GoalPost; break;
      case ObservationType::LineCorner: kind = FeatureKind::Corner; break;
      case ObservationType::FieldLine: kind = FeatureKind::LinePoint; break;
      case ObservationType::CentreCircle: kind = FeatureKind::CentreCircle; break;
      case ObservationType::PenaltyCross: kind = FeatureKind::PenaltyCross; break;
      default: continue;  // a type this adapter does not know yet
    }
    if (v.num_features < blackboard::kMaxFeatures) v.features[v.num_features++] = {kind, p, o.camera};
  }
  return v;
}

}  // namespace agent::perception
