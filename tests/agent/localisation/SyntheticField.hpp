// A synthetic robot for localisation and ball tests: a true pose walked by
// commanded steps, odometry with a bias and noise, and a detector that sees
// the field model's landmarks and line points within a field of view and
// range, with noise on distance and bearing and missed detections.
// Units: mm, rad, s. Deterministic from the seed.
#pragma once

#include <cmath>
#include <vector>

#include "agent/blackboard/Blackboard.hpp"
#include "agent/localisation/FieldModel.hpp"
#include "agent/localisation/Localiser.hpp"
#include "common/random/Random.hpp"

namespace loc_test {

namespace bb = agent::blackboard;
namespace localisation = agent::localisation;

struct DetectorSpec {
  double half_fov = 1.05;         // rad: the camera's 30 deg plus the head scanning +-30 deg
  double max_point = 4500;        // mm
  double max_line = 2500;         // mm
  double min_range = 250;         // mm
  double p_detect = 0.7;          // per landmark per frame
  double distance_fraction = 0.08;  // 1 sigma, of the distance
  double bearing_sigma = 0.03;    // rad
  int line_points = 10;           // per frame at most
};

class SyntheticRobot {
 public:
  SyntheticRobot(uint64_t seed, bb::FieldPose start, DetectorSpec det = {})
      : rng_(seed), truth_(start), det_(det), field_(localisation::FieldModel::spl2017()) {
    lm_ = field_.landmarks();
    for (const localisation::LineSegment& s : field_.lines()) {
      const double len = std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
      for (double t = 0; t <= len; t += 200) {
        line_pts_.push_back({s.a.x + (s.b.x - s.a.x) * t / len, s.a.y + (s.b.y - s.a.y) * t / len});
      }
    }
    for (int k = 0; k < 48; ++k)
      line_pts_.push_back({750 * std::cos(k * 2 * M_PI / 48), 750 * std::sin(k * 2 * M_PI / 48)});
  }

  // Walks one frame of dt s at (forward mm/s, left mm/s, turn rad/s). Returns
  // the odometry step the robot code would see (5 % overestimate plus noise).
  void walk(double forward, double left, double turn, double dt, double* of, double* ol, double* ot) {
    const double f = forward * dt, l = left * dt, t = turn * dt;
    const double mid = truth_.theta + 0.5 * t;
    truth_.x += std::cos(mid) * f - std::sin(mid) * l;
    truth_.y += std::sin(mid) * f + std::cos(mid) * l;
    truth_.theta = localisation::wrapAngle(truth_.theta + t);
    *of = f * 1.05 + rng_.gaussian(1.0);
    *ol = l * 1.05 + rng_.gaussian(1.0);
    *ot = t * 1.05 + rng_.gaussian(0.002);
  }
  void teleport(const bb::FieldPose& p) { truth_ = p; }
  const bb::FieldPose& truth() const { return truth_; }

  // What the detector reports from the true pose.
  bb::VisionMeasurements see(double time) {
    bb::VisionMeasurements v;
    v.time = time;
    auto rel = [&](double fx, double fy, double* d, double* b) {
      const double dx = fx - truth_.x, dy = fy - truth_.y;
      const double c = std::cos(truth_.theta), s = std::sin(truth_.theta);
      const double rx = c * dx + s * dy, ry = -s * dx + c * dy;
      *d = std::hypot(rx, ry);
      *b = std::atan2(ry, rx);
    };
    auto push = [&](bb::FeatureKind k, double d, double b) {
      if (v.num_features >= bb::kMaxFeatures) return;
      d *= 1 + rng_.gaussian(det_.distance_fraction);
      b += rng_.gaussian(det_.bearing_sigma);
      bb::FieldFeature& f = v.features[v.num_features++];
      f.kind = k;
      f.where.x = static_cast<float>(d * std::cos(b));
      f.where.y = static_cast<float>(d * std::sin(b));
      f.where.distance = static_cast<float>(d);
      f.where.heading = static_cast<float>(b);
    };
    for (const localisation::Landmark& l : lm_) {
      double d, b;
      rel(l.at.x, l.at.y, &d, &b);
      if (d < det_.min_range || d > det_.max_point || std::fabs(b) > det_.half_fov) continue;
      if (rng_.uniform() > det_.p_detect) continue;
      push(l.kind, d, b);
    }
    std::vector<std::pair<double, double>> seen;
    for (const localisation::Vec2& p : line_pts_) {
      double d, b;
      rel(p.x, p.y, &d, &b);
      if (d < det_.min_range || d > det_.max_line || std::fabs(b) > det_.half_fov) continue;
      seen.push_back({d, b});
    }
    for (int k = 0; k < det_.line_points && !seen.empty(); ++k) {
      const size_t i = static_cast<size_t>(rng_.uniform() * seen.size()) % seen.size();
      push(bb::FeatureKind::LinePoint, seen[i].first, seen[i].second);
    }
    return v;
  }

  common::random::Random& rng() { return rng_; }

 private:
  common::random::Random rng_;
  bb::FieldPose truth_;
  DetectorSpec det_;
  localisation::FieldModel field_;
  std::vector<localisation::Landmark> lm_;
  std::vector<localisation::Vec2> line_pts_;
};

inline double poseError(const bb::FieldPose& a, const bb::FieldPose& b) { return std::hypot(a.x - b.x, a.y - b.y); }
inline double headingError(const bb::FieldPose& a, const bb::FieldPose& b) {
  return std::fabs(localisation::wrapAngle(a.theta - b.theta));
}

}  // namespace loc_test
