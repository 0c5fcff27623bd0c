#include "agent/perception/VisionAdapter.hpp"

#include <algorithm>
#include <cmath>

namespace agent::perception {

using blackboard::FeatureKind;
using common::libagent::ObservationType;

namespace {
// Completes a detection: x, y from distance/heading when only those are set.
bool toPoint(const common::libagent::Observation& o, double max_distance, blackboard::RRPoint& p) {
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
  const int n = std::min<int>(frame.num_observations, common::libagent::kMaxObservations);
  for (int i = 0; i < n; ++i) {
    const common::libagent::Observation& o = frame.observations[i];
    blackboard::RRPoint p;
    if (!toPoint(o, cfg.max_distance, p)) continue;
    FeatureKind kind;
    switch (o.type) {
      case ObservationType::Ball:
        if (!v.ball_seen || p.distance < v.ball.distance) v.ball = p;
        v.ball_seen = true;
        continue;
      case ObservationType::Robot:
        if (v.num_robots < blackboard::kMaxSeenRobots)
          v.robots[v.num_robots++] = {p, o.team, o.colour, (o.flags & common::libagent::kObservationRobotFallen) != 0};
        continue;
      case ObservationType::GoalPost: kind = FeatureKind::GoalPost; break;
      case ObservationType::LineCorner: kind = FeatureKind::Corner; break;
      case ObservationType::FieldLine: {
        // A piece from (x, y) to (x2, y2), or a single point when no second end is given.
        const double dx = o.x2 - p.x, dy = o.y2 - p.y;
        const double len = (o.x2 == 0 && o.y2 == 0) || !std::isfinite(dx) || !std::isfinite(dy) ? 0.0
                                                                                                 : std::hypot(dx, dy);
        const int n = std::max(1, static_cast<int>(std::ceil(len / std::max(50.0, cfg.line_point_spacing) - 1e-9)));
        for (int k = 0; k <= n && v.num_features < blackboard::kMaxFeatures; ++k) {
          if (k == n && len == 0) break;
          const double f = n > 0 && len > 0 ? static_cast<double>(k) / n : 0.0;
          common::libagent::Observation q = o;
          q.x = static_cast<float>(p.x + f * dx);
          q.y = static_cast<float>(p.y + f * dy);
          q.distance = 0;
          blackboard::RRPoint lp;
          if (toPoint(q, cfg.max_distance, lp)) v.features[v.num_features++] = {FeatureKind::LinePoint, lp, o.camera};
        }
        continue;
      }
      case ObservationType::CentreCircle: kind = FeatureKind::CentreCircle; break;
      case ObservationType::PenaltyCross: kind = FeatureKind::PenaltyCross; break;
      default: continue;  // a type this adapter does not know yet
    }
    if (v.num_features < blackboard::kMaxFeatures) {
      blackboard::FieldFeature& f = v.features[v.num_features++];
      f = {kind, p, o.camera};
      if (kind == FeatureKind::Corner) f.shape = static_cast<blackboard::CornerShape>(static_cast<int>(o.corner));
    }
  }
  return v;
}

}  // namespace agent::perception
