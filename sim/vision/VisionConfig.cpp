#include "sim/vision/VisionConfig.hpp"

#include <algorithm>

#include "sim/world/ConfigError.hpp"

namespace simswift::vision {

const char* featureKey(Feature f) {
  switch (f) {
    case Feature::Ball: return "ball";
    case Feature::GoalPost: return "goal_posts";
    case Feature::Robot: return "robots";
    case Feature::PenaltyMark: return "penalty_marks";
    case Feature::CentreCircle: return "centre_circle";
    case Feature::Corner: return "corners";
    case Feature::Line: return "lines";
  }
  return "?";
}

double DetectorSpec::probability(double d) const {
  if (!enabled || d < min_distance_mm || d > max_distance_mm) return 0.0;
  if (d <= falloff_start_mm || max_distance_mm <= falloff_start_mm) return p_near;
  const double s = (d - falloff_start_mm) / (max_distance_mm - falloff_start_mm);
  return p_near + (p_at_max - p_near) * s;
}

std::array<DetectorSpec, kNumFeatures> VisionConfig::defaultDetectors() {
  std::array<DetectorSpec, kNumFeatures> d{};
  auto set = [&](Feature f, double max_mm, double falloff_mm, double p_at_max, double orient_deg) -> DetectorSpec& {
    DetectorSpec& s = d[static_cast<int>(f)];
    s.max_distance_mm = max_mm;
    s.falloff_start_mm = falloff_mm;
    s.p_at_max = p_at_max;
    s.orientation_sigma_deg = orient_deg;
    return s;
  };
  // Ball: the thesis's 2500 mm reliable range; a ball on a line is harder
  // (white on white, thesis section 6.1): assumed 0.6 of the usual rate.
  set(Feature::Ball, 2500, 1500, 0.7, 0).on_line_factor = 0.6;
  set(Feature::GoalPost, 4500, 3000, 0.6, 0);
  set(Feature::Robot, 3000, 2000, 0.6, 15);
  set(Feature::PenaltyMark, 2500, 1500, 0.6, 0);
  set(Feature::CentreCircle, 3000, 2000, 0.7, 3);
  set(Feature::Corner, 3000, 2000, 0.7, 3);
  set(Feature::Line, 3500, 2500, 0.8, 0);
  return d;
}

namespace {

DetectorSpec readDetector(const YamlReader& r, DetectorSpec s, bool is_ball) {
  s.enabled = r.boolean("enabled", s.enabled);
  s.min_distance_mm = r.number("min_distance_mm", s.min_distance_mm, Range::closed(0, 20000));
  s.max_distance_mm = r.number("max_distance_mm", s.max_distance_mm, Range::closed(0, 20000));
  if (s.max_distance_mm <= s.min_distance_mm)
    r.fail("max_distance_mm", "must be greater than min_distance_mm (" + std::to_string(s.min_distance_mm) + ")");
  s.p_near = r.number("p_near", s.p_near, Range::closed(0, 1));
  s.p_at_max = r.number("p_at_max", s.p_at_max, Range::closed(0, 1));
  // An absent falloff_start_mm follows a shortened max distance.
  s.falloff_start_mm = r.number("falloff_start_mm", std::min(s.falloff_start_mm, s.max_distance_mm),
                                Range::closed(0, 20000));
  if (s.falloff_start_mm > s.max_distance_mm)
    r.fail("falloff_start_mm", "must not exceed max_distance_mm (" + std::to_string(s.max_distance_mm) + ")");
  s.distance_sigma_mm = r.number("distance_sigma_mm", s.distance_sigma_mm, Range::closed(0, 5000));
  s.distance_sigma_fraction = r.number("distance_sigma_fraction", s.distance_sigma_fraction, Range::closed(0, 1));
  s.bearing_sigma_deg = r.number("bearing_sigma_deg", s.bearing_sigma_deg, Range::closed(0, 90));
  s.elevation_sigma_deg = r.number("elevation_sigma_deg", s.elevation_sigma_deg, Range::closed(0, 10));
  s.orientation_sigma_deg = r.number("orientation_sigma_deg", s.orientation_sigma_deg, Range::closed(0, 180));
  s.false_positive_rate = r.number("false_positive_rate", s.false_positive_rate, Range::closed(0, 1));
  if (is_ball) {
    s.on_line_factor = r.number("on_line_factor", s.on_line_factor, Range::closed(0, 1));
  }
  r.finish();
  return s;
}

}  // namespace

VisionConfig readVisionConfig(const YamlReader& r, VisionConfig c) {
  if (r.has("preset") && r.choice("preset", "simswift2017", {"simswift2017"}) == "simswift2017") {
    c.ball_model = BallModel::Thesis2017;
    c[Feature::Ball].max_distance_mm = 2500;  // SimVisionAdapter's range
    c[Feature::Ball].false_positive_rate = 0;
  }
  c.enabled = r.boolean("enabled", c.enabled);
  c.noise = r.boolean("noise", c.noise);
  if (r.has("hfov_deg")) c.hfov_deg = r.number("hfov_deg", 0, Range::closed(1, 179));
  if (r.has("vfov_deg")) c.vfov_deg = r.number("vfov_deg", 0, Range::closed(1, 179));
  c.camera_offset_mm = r.number("camera_offset_mm", c.camera_offset_mm, Range::closed(0, 100));
  c.lying_tilt_deg = r.number("lying_tilt_deg", c.lying_tilt_deg, Range::closed(1, 180));
  c.falling_rate_dps = r.number("falling_rate_dps", c.falling_rate_dps, Range::positive());
  c.falling_tilt_deg = r.number("falling_tilt_deg", c.falling_tilt_deg, Range::closed(0, 180));
  c.occlusion_margin_mm = r.number("occlusion_margin_mm", c.occlusion_margin_mm, Range::closed(0, 200));
  c.line_step_mm = r.number("line_step_mm", c.line_step_mm, Range::closed(5, 1000));
  c.min_line_mm = r.number("min_line_mm", c.min_line_mm, Range::closed(0, 10000));
  c.circle_min_fraction = r.number("circle_min_fraction", c.circle_min_fraction, Range::closed(0, 1));
  for (int i = 0; i < kNumFeatures; ++i) {
    const Feature f = static_cast<Feature>(i);
    if (auto m = r.optionalMap(featureKey(f))) c.detectors[i] = readDetector(*m, c.detectors[i], f == Feature::Ball);
  }
  r.finish();
  return c;
}

}  // namespace simswift::vision
