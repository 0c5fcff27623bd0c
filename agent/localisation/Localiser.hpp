// Localisation: a particle filter over the robot's field pose (x, y, theta)
// driven by odometry and the vision adapter's field features.
//
// - Prediction: each frame's odometry step (robot frame) with noise
//   proportional to the step plus a floor.
// - Correction: point features (goal posts, penalty crosses, the centre
//   circle, line corners) are matched to the nearest field landmark of their
//   kind (distance and bearing errors, Gaussian); line points by their
//   distance to the nearest painted line. Each observation's likelihood is
//   mixed with an outlier floor so one false detection cannot kill the filter.
// - Re-localisation (augmented MCL): when recent observations fit much worse
//   than they used to, particles are injected at poses the frame's
//   observations imply (pairs of point features, or one point feature and a
//   sampled heading), ranked by how well the whole frame fits them.
// - Symmetry: the 2017 field is point-symmetric about the centre spot (both
//   goals alike), so every injected pose P has a mirror twin P' = (-x, -y,
//   theta + pi) that fits equally well. The filter keeps the twin nearer the
//   current belief's modes, whose side goes back to the starting side the
//   game state gave (own half, sideline entry), so the symmetric pose is
//   rejected. (A robot carried across the halfway line cannot tell; neither
//   can a real one on this field without teammates.)
// - Own-half bound: after a sideline entry or a penalty return the robot
//   stands in its own half, and it can since have come no further up the
//   field than the distance it walked. Particles beyond that bound (x above
//   the furthest placement plus the walked distance) lose weight, and an
//   injected pose beyond it gives way to its twin. Near the halfway line the
//   twins are close and both near the entry belief's modes, so this is what
//   tells them apart in the first metres. B-Human's public code release
//   reasons the same way (SideInformationProvider: a robot must be in its
//   own half given the distance walked since it was placed).
// - Flip / kidnap: when the estimate moves more than odometry explains
//   (jump_distance / jump_angle) the estimate's `jumped` flag is raised.
//
// Units: mm, rad, s. Field frame as in FieldModel.hpp. Deterministic: all
// randomness from the seed.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "agent/blackboard/Blackboard.hpp"
#include "agent/localisation/FieldModel.hpp"
#include "common/random/Random.hpp"

namespace agent::localisation {

struct LocaliserConfig {
  int particles = 200;
  uint64_t seed = 1;
  // Odometry noise per frame: sigma = floor + fraction * step.
  double odo_trans_fraction = 0.15;  // of the distance walked
  double odo_trans_floor = 3.0;      // mm
  double odo_rot_fraction = 0.15;    // of the turn
  double odo_rot_floor = 0.004;      // rad
  double odo_rot_per_mm = 0.0002;    // rad of heading noise per mm walked
  // Measurement model (1 sigma).
  double distance_fraction = 0.12;   // of the measured distance
  double distance_floor = 60.0;      // mm
  double bearing_sigma = 0.08;       // rad
  double line_floor = 60.0;          // mm, line points: floor + fraction * distance
  double line_fraction = 0.08;
  double outlier = 0.1;              // likelihood floor of any one observation
  int max_line_points = 6;           // per frame (they are correlated)
  // Re-localisation.
  double slow_rate = 0.02, fast_rate = 0.25;  // averaging rates of the frame likelihood
  double inject_ratio = 0.6;         // inject when fast < ratio * slow
  double inject_below = 0.3;         // ... or when fast (per-observation fit, 0..1) is below this
  double inject_fraction = 0.25;     // of the particles replaced per frame at most
  int max_candidates = 800;          // poses evaluated per injection
  int inject_modes = 12;             // distinct poses injected at once
  // Prior weight of an injected particle relative to one carried forward (a
  // kidnap is rare): a pose that explains one frame -- a false detection,
  // or one feature alone -- cannot take the belief over in that frame; it
  // must keep fitting better than the belief for a few frames.
  double inject_prior = 0.05;
  // Probing: even when the belief fits, every probe_interval s a few
  // particles (probe_fraction) go to the poses the frame implies, so an alias
  // that fitted one frame as well as the truth cannot hold the belief for long.
  double probe_interval = 1.0;       // s
  double probe_fraction = 0.05;
  double min_pair_distance = 300;    // mm, point features closer than this make no pair
  int heading_samples = 36;          // single-feature candidates
  // Flip / kidnap detection.
  double jump_distance = 700;        // mm
  double jump_angle = 0.6;           // rad
  // Initial poses.
  double penalty_return_x = -3200;   // mm, where a penalised robot comes back (own penalty mark's x)
  double entry_x_min = -4000;        // mm, the sideline-entry belief's x range (own half,
  double entry_x_max = -300;         //   clear of the goal area and the halfway line)
  // Own-half bound (above); off: the twin choice by the belief's modes alone.
  bool own_half_bound = true;
  double bound_margin = 500;         // mm beyond the furthest placement (a fall, a shove)
  double bound_walk_factor = 1.3;    // of the odometry's distance (slip, odometry error)
  double bound_weight = 0.01;        // a particle's weight factor per frame beyond the bound
};

// Where to (re)start the belief.
enum class InitialPose {
  SidelineEntry,   // on either touch line in the own half, facing the field
  PenaltyReturn,   // on either touch line at penalty_return_x, facing the field
  OwnHalf,         // anywhere in the own half, any heading (no game state)
};

struct Particle {
  double x = 0, y = 0, theta = 0;  // mm, mm, rad
  double w = 1;
};

class Localiser {
 public:
  explicit Localiser(const LocaliserConfig& cfg = {}, const FieldModel& field = FieldModel::spl2017());

  void reset(InitialPose where);
  // A known pose with spread (mm, rad, 1 sigma).
  void resetTo(const blackboard::FieldPose& p, double sd_xy = 100, double sd_theta = 0.1);
  // The own-half bound: the largest x (mm) the robot can be at; kNoBound
  // when unbounded (a known start, or walked far enough for any x).
  static constexpr double kNoBound = std::numeric_limits<double>::infinity();
  double ownHalfBound() const { return bound_x_; }

  // One frame: odometry step since the previous frame (robot frame of the
  // previous pose: forward mm, left mm, turn rad), then the observations.
  // `time` s is the frame time; `fallen` skips the correction.
  void update(double forward, double left, double turn, const blackboard::VisionMeasurements& vision,
              double time, bool fallen = false);

  const blackboard::LocalisationEstimate& estimate() const { return estimate_; }
  const std::vector<Particle>& particles() const { return particles_; }
  const LocaliserConfig& config() const { return cfg_; }

  // Likelihood of one frame's features at a pose (product over features, each
  // mixed with the outlier floor), for tests and tools.
  double frameLikelihood(const Particle& pose, const blackboard::VisionMeasurements& vision) const;

 private:
  struct Obs {
    blackboard::FeatureKind kind;
    double x, y, d, b;  // mm robot-relative, distance, bearing
    blackboard::CornerShape shape;  // corners: L / T / X when the detector told
    // Per observation, not per particle (likelihood() runs per particle):
    double sigma = 0;    // mm, line points: the line distance's deviation
    double inv_sd2 = 0;  // 1/mm^2, point features: along the line of sight
    double inv_sb2 = 0;  // 1/mm^2, point features: across it
  };
  // Landmarks an observation may be: same kind, and same corner shape when known.
  const std::vector<Vec2>& candidatesFor(const Obs& o) const;
  bool matches(const Obs& o, const Landmark& l) const {
    return l.kind == o.kind && (o.shape == blackboard::CornerShape::Unknown || l.shape == o.shape);
  }
  void collect(const blackboard::VisionMeasurements& vision);
  double likelihood(const Particle& p) const;
  void predict(double forward, double left, double turn);
  void resample();
  void inject(int count);
  void candidates(std::vector<Particle>& out) const;
  void computeEstimate(double time, double forward, double left, double turn);

  LocaliserConfig cfg_;
  FieldModel field_;
  std::vector<Landmark> landmarks_;
  FieldLines lines_;  // the straight lines and the centre circle, for line points
  std::vector<Vec2> by_kind_[static_cast<int>(blackboard::FeatureKind::NUM_KINDS)];  // landmark positions
  std::vector<Vec2> corners_by_shape_[4];  // indexed by CornerShape
  common::random::Random rng_;
  std::vector<Particle> particles_;
  // Cost of a pose under the current belief's modes (smaller = more
  // believable): min over modes of d^2 / (2 sigma^2) - log(weight).
  double modeCost(double x, double y) const;

  std::vector<Obs> obs_;  // this frame's, filtered
  struct Mode {
    double x, y, w;  // mm, mm, weight
  };
  std::vector<Mode> modes_;
  double w_slow_ = 0, w_fast_ = 0;
  double bound_x_ = kNoBound;  // mm: the own-half bound (ownHalfBound())
  bool beyondBound(double x) const { return x > bound_x_; }
  double last_probe_ = -1e9;  // s
  bool have_estimate_ = false;
  blackboard::LocalisationEstimate estimate_;
};

double wrapAngle(double a);

}  // namespace agent::localisation
