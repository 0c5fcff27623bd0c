#include "agent/localisation/Localiser.hpp"

#include <algorithm>
#include <cmath>

#include "common/field/FieldFacts.hpp"

namespace agent::localisation {

using blackboard::FeatureKind;

namespace {
constexpr double kPi = 3.14159265358979323846;

double sq(double v) { return v * v; }
constexpr double kPenaltyReturnSpread = 200;  // mm, 1 sigma along the touch line
}  // namespace

double wrapAngle(double a) {
  if (a > -kPi && a <= kPi) return a;  // the usual case, without trigonometry
  a = std::fmod(a + kPi, 2 * kPi);
  if (a <= 0) a += 2 * kPi;
  return a - kPi;
}

Localiser::Localiser(const LocaliserConfig& cfg, const FieldModel& field)
    : cfg_(cfg), field_(field), landmarks_(field.landmarks()), lines_(field.lines(), field.centre_circle_radius), rng_(cfg.seed) {
  for (const Landmark& l : landmarks_) {
    by_kind_[static_cast<int>(l.kind)].push_back(l.at);
    if (l.kind == FeatureKind::Corner) corners_by_shape_[static_cast<int>(l.shape)].push_back(l.at);
  }
  if (cfg_.particles < 10) cfg_.particles = 10;
  reset(InitialPose::OwnHalf);
}

void Localiser::reset(InitialPose where) {
  particles_.assign(cfg_.particles, Particle{});
  const double hx = field_.halfLength(), hy = field_.halfWidth();
  for (size_t i = 0; i < particles_.size(); ++i) {
    Particle& p = particles_[i];
    const double side = (i % 2 == 0) ? 1.0 : -1.0;  // left / right touch line
    switch (where) {
      case InitialPose::SidelineEntry:
        p.x = rng_.uniform(cfg_.entry_x_min, cfg_.entry_x_max);
        p.y = side * hy + rng_.gaussian(50);
        p.theta = -side * kPi / 2 + rng_.gaussian(0.1);
        break;
      case InitialPose::PenaltyReturn:
        p.x = cfg_.penalty_return_x + rng_.gaussian(kPenaltyReturnSpread);
        p.y = side * hy + rng_.gaussian(50);
        p.theta = -side * kPi / 2 + rng_.gaussian(0.1);
        break;
      case InitialPose::OwnHalf:
        p.x = rng_.uniform(-hx, 0);
        p.y = rng_.uniform(-hy, hy);
        p.theta = rng_.uniform(-kPi, kPi);
        break;
    }
    p.w = 1.0 / particles_.size();
  }
  // The furthest up the field a placement of this kind puts the robot.
  const double placed_max_x = where == InitialPose::SidelineEntry   ? cfg_.entry_x_max
                              : where == InitialPose::PenaltyReturn ? cfg_.penalty_return_x + 3 * kPenaltyReturnSpread
                                                                    : 0.0;
  bound_x_ = cfg_.own_half_bound ? placed_max_x + cfg_.bound_margin : kNoBound;
  w_slow_ = w_fast_ = 0;
  have_estimate_ = false;
  computeEstimate(estimate_.time, 0, 0, 0);
  estimate_.jumped = false;
}

void Localiser::resetTo(const blackboard::FieldPose& pose, double sd_xy, double sd_theta) {
  particles_.assign(cfg_.particles, Particle{});
  for (Particle& p : particles_) {
    p.x = pose.x + rng_.gaussian(sd_xy);
    p.y = pose.y + rng_.gaussian(sd_xy);
    p.theta = wrapAngle(pose.theta + rng_.gaussian(sd_theta));
    p.w = 1.0 / particles_.size();
  }
  bound_x_ = kNoBound;  // a known start: the team placed it, anywhere
  w_slow_ = w_fast_ = 0;
  have_estimate_ = false;
  computeEstimate(estimate_.time, 0, 0, 0);
  estimate_.jumped = false;
}

void Localiser::collect(const blackboard::VisionMeasurements& vision) {
  obs_.clear();
  std::vector<Obs> lines;
  for (int i = 0; i < vision.num_features && i < blackboard::kMaxFeatures; ++i) {
    const blackboard::FieldFeature& f = vision.features[i];
    const double d = std::hypot(f.where.x, f.where.y);
    if (!(d > 1.0) || d > 7000.0) continue;  // behind the feet or beyond any useful range
    Obs o{f.kind, f.where.x, f.where.y, d, std::atan2(f.where.y, f.where.x),
          f.kind == FeatureKind::Corner ? f.shape : blackboard::CornerShape::Unknown};
    o.sigma = cfg_.line_floor + cfg_.line_fraction * d;
    o.inv_sd2 = 1.0 / sq(cfg_.distance_floor + cfg_.distance_fraction * d);
    o.inv_sb2 = 1.0 / sq(d * cfg_.bearing_sigma);
    (f.kind == FeatureKind::LinePoint ? lines : obs_).push_back(o);
  }
  // Line points from one frame are strongly correlated: use a few, spread out.
  const int n = static_cast<int>(lines.size()), m = std::min(n, cfg_.max_line_points);
  for (int k = 0; k < m; ++k) obs_.push_back(lines[static_cast<size_t>(k) * n / m]);
}

double Localiser::likelihood(const Particle& p) const {
  const double c = std::cos(p.theta), s = std::sin(p.theta);
  double l = 1.0;
  for (const Obs& o : obs_) {
    double fit = 0;
    if (o.kind == FeatureKind::LinePoint) {
      const Vec2 f{p.x + c * o.x - s * o.y, p.y + s * o.x + c * o.y};
      fit = std::exp(-0.5 * sq(lines_.distance(f) / o.sigma));
    } else {
      // The landmark in the particle's robot frame minus the observation,
      // split along and across the line of sight: the along part is the
      // distance error, the across part / distance the bearing error.
      const double ux = o.x / o.d, uy = o.y / o.d;
      const double inv_sd2 = o.inv_sd2, inv_sb2 = o.inv_sb2;
      double best = 1e300;
      for (const Vec2& lm : candidatesFor(o)) {
        const double dx = lm.x - p.x, dy = lm.y - p.y;
        const double ex = c * dx + s * dy - o.x, ey = -s * dx + c * dy - o.y;
        const double along = ex * ux + ey * uy, across = ey * ux - ex * uy;
        best = std::min(best, along * along * inv_sd2 + across * across * inv_sb2);
      }
      fit = best < 60 ? std::exp(-0.5 * best) : 0.0;
    }
    l *= cfg_.outlier + (1.0 - cfg_.outlier) * fit;
  }
  return l;
}

const std::vector<Vec2>& Localiser::candidatesFor(const Obs& o) const {
  if (o.kind == FeatureKind::Corner && o.shape != blackboard::CornerShape::Unknown)
    return corners_by_shape_[static_cast<int>(o.shape)];
  return by_kind_[static_cast<int>(o.kind)];
}

double Localiser::frameLikelihood(const Particle& pose, const blackboard::VisionMeasurements& vision) const {
  Localiser* self = const_cast<Localiser*>(this);
  const std::vector<Obs> saved = obs_;
  self->collect(vision);
  const double l = likelihood(pose);
  self->obs_ = saved;
  return l;
}

void Localiser::predict(double forward, double left, double turn) {
  const double step = std::hypot(forward, left);
  const double st = cfg_.odo_trans_floor + cfg_.odo_trans_fraction * step;
  const double sr = cfg_.odo_rot_floor + cfg_.odo_rot_fraction * std::fabs(turn) + cfg_.odo_rot_per_mm * step;
  for (Particle& p : particles_) {
    const double f = forward + rng_.gaussian(st), l = left + rng_.gaussian(st);
    const double t = turn + rng_.gaussian(sr);
    // Move along the mid-step heading.
    const double mid = p.theta + 0.5 * t;
    p.x += std::cos(mid) * f - std::sin(mid) * l;
    p.y += std::sin(mid) * f + std::cos(mid) * l;
    p.theta = wrapAngle(p.theta + t);
  }
}

void Localiser::resample() {
  // Low-variance (systematic) resampling.
  const size_t n = particles_.size();
  std::vector<Particle> out;
  out.reserve(n);
  const double step = 1.0 / n;
  double u = rng_.uniform() * step, acc = particles_[0].w;
  size_t i = 0;
  for (size_t k = 0; k < n; ++k) {
    while (u > acc && i + 1 < n) acc += particles_[++i].w;
    out.push_back(particles_[i]);
    out.back().w = step;
    u += step;
  }
  particles_.swap(out);
}

void Localiser::candidates(std::vector<Particle>& out) const {
  out.clear();
  // Poses on the carpet: the lines plus the border strip (mm).
  const double hx = field_.halfLength() + common::field::kBorderStripWidth, hy = field_.halfWidth() + common::field::kBorderStripWidth;
  auto add = [&](double x, double y, double theta) {
    if (std::fabs(x) < hx && std::fabs(y) < hy && static_cast<int>(out.size()) < cfg_.max_candidates)
      out.push_back({x, y, wrapAngle(theta), 0});
  };
  std::vector<const Obs*> points;
  for (const Obs& o : obs_)
    if (o.kind != FeatureKind::LinePoint) points.push_back(&o);
  // Two point features fix the pose: the heading from the direction between
  // them, the position from either.
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = i + 1; j < points.size(); ++j) {
      const Obs &a = *points[i], &b = *points[j];
      const double dz = std::hypot(b.x - a.x, b.y - a.y);
      if (dz < cfg_.min_pair_distance) continue;
      const double tol = 100.0 + cfg_.distance_fraction * std::max(a.d, b.d);
      for (const Landmark& la : landmarks_) {
        if (!matches(a, la)) continue;
        for (const Landmark& lb : landmarks_) {
          if (!matches(b, lb) || (&la == &lb)) continue;
          if (std::fabs(std::hypot(lb.at.x - la.at.x, lb.at.y - la.at.y) - dz) > tol) continue;
          const double theta = std::atan2(lb.at.y - la.at.y, lb.at.x - la.at.x) - std::atan2(b.y - a.y, b.x - a.x);
          const double c = std::cos(theta), s = std::sin(theta);
          const double xa = la.at.x - (c * a.x - s * a.y), ya = la.at.y - (s * a.x + c * a.y);
          const double xb = lb.at.x - (c * b.x - s * b.y), yb = lb.at.y - (s * b.x + c * b.y);
          add(0.5 * (xa + xb), 0.5 * (ya + yb), theta);
        }
      }
    }
  // One point feature: a circle of poses around each landmark of its kind,
  // one per sampled heading (the line points pick among them).
  if (points.size() < 2) {
    for (const Obs* o : points)
      for (const Landmark& lm : landmarks_) {
        if (!matches(*o, lm)) continue;
        for (int k = 0; k < cfg_.heading_samples; ++k) {
          const double theta = 2 * kPi * k / cfg_.heading_samples;
          const double c = std::cos(theta), s = std::sin(theta);
          add(lm.at.x - (c * o->x - s * o->y), lm.at.y - (s * o->x + c * o->y), theta);
        }
      }
  }
}

void Localiser::inject(int count) {
  std::vector<Particle> cand;
  candidates(cand);
  if (cand.empty() || count <= 0) return;
  // Of each mirror pair keep the twin inside the own-half bound, else the
  // one nearer the current belief (the side the robot started on, carried
  // forward by odometry).
  std::vector<Particle> kept;
  for (Particle& c : cand) {
    const bool out = beyondBound(c.x), twin_out = beyondBound(-c.x);
    if (out && !twin_out) continue;
    if (out == twin_out && !modes_.empty() && modeCost(c.x, c.y) > modeCost(-c.x, -c.y)) continue;
    c.w = likelihood(c);
    kept.push_back(c);
  }
  if (kept.empty()) return;
  std::stable_sort(kept.begin(), kept.end(), [](const Particle& a, const Particle& b) { return a.w > b.w; });
  // Distinct poses only (a few aliases can fit one frame about as well as the
  // truth; keeping several lets the next frames decide between them).
  std::vector<const Particle*> picks;
  const double best = kept[0].w;
  for (const Particle& c : kept) {
    if (c.w < 1e-4 * best || static_cast<int>(picks.size()) >= cfg_.inject_modes) break;
    bool distinct = true;
    for (const Particle* q : picks)
      if (sq(c.x - q->x) + sq(c.y - q->y) < sq(500.0) && std::fabs(wrapAngle(c.theta - q->theta)) < 0.5) {
        distinct = false;
        break;
      }
    if (distinct) picks.push_back(&c);
  }
  // Replace the worst particles by the picks (round robin, jittered). Weights
  // stay unnormalised: prior inject_prior / N times the frame's likelihood.
  std::vector<size_t> order(particles_.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return particles_[a].w < particles_[b].w; });
  for (int k = 0; k < count && k < static_cast<int>(order.size()); ++k) {
    const Particle& c = *picks[k % picks.size()];
    Particle& p = particles_[order[k]];
    p.x = c.x + rng_.gaussian(40);
    p.y = c.y + rng_.gaussian(40);
    p.theta = wrapAngle(c.theta + rng_.gaussian(0.03));
    p.w = cfg_.inject_prior * likelihood(p) / particles_.size();
  }
}

double Localiser::modeCost(double x, double y) const {
  constexpr double kSigma = 2000.0;  // mm: how far a belief mode vouches for its surroundings
  double best = 1e300;
  for (const Mode& m : modes_)
    if (m.w > 0) best = std::min(best, (sq(x - m.x) + sq(y - m.y)) / (2 * kSigma * kSigma) - std::log(m.w));
  return best;
}

void Localiser::update(double forward, double left, double turn, const blackboard::VisionMeasurements& vision,
                       double time, bool fallen) {
  predict(forward, left, turn);
  if (bound_x_ != kNoBound) {
    bound_x_ += cfg_.bound_walk_factor * std::hypot(forward, left);
    if (bound_x_ > field_.halfLength() + common::field::kBorderStripWidth) bound_x_ = kNoBound;  // any x now
  }
  if (fallen) {
    // Falling turns the body unpredictably: widen the heading.
    for (Particle& p : particles_) p.theta = wrapAngle(p.theta + rng_.gaussian(0.01));
    computeEstimate(time, forward, left, turn);
    return;
  }
  collect(vision);
  if (!obs_.empty()) {
    // Weight by the frame's likelihood; the per-observation geometric mean of
    // the weighted average tracks how well the belief explains what is seen.
    double fit = 0;
    const double inv_n = 1.0 / obs_.size();
    for (Particle& p : particles_) {
      const double l = likelihood(p);
      fit += p.w * std::pow(l, inv_n);
      p.w *= l;  // prior (summing to 1) times likelihood: unnormalised
      if (beyondBound(p.x)) p.w *= cfg_.bound_weight;
    }
    if (w_slow_ == 0) w_slow_ = w_fast_ = fit;
    w_slow_ += cfg_.slow_rate * (fit - w_slow_);
    w_fast_ += cfg_.fast_rate * (fit - w_fast_);
    if (w_fast_ < cfg_.inject_ratio * w_slow_ || w_fast_ < cfg_.inject_below) {
      inject(static_cast<int>(cfg_.inject_fraction * particles_.size()));
      last_probe_ = time;
    } else if (time - last_probe_ >= cfg_.probe_interval) {
      inject(static_cast<int>(cfg_.probe_fraction * particles_.size()));
      last_probe_ = time;
    }
    double total = 0;
    for (const Particle& p : particles_) total += p.w;
    if (!(total > 1e-300)) {
      for (Particle& p : particles_) p.w = 1.0;
      total = static_cast<double>(particles_.size());
    }
    for (Particle& p : particles_) p.w /= total;
    double sum2 = 0;
    for (const Particle& p : particles_) sum2 += p.w * p.w;
    if (1.0 / sum2 < 0.5 * particles_.size()) resample();
  }
  computeEstimate(time, forward, left, turn);
}

void Localiser::computeEstimate(double time, double forward, double left, double turn) {
  // Greedy clustering into modes (hypotheses); the estimate is the weighted
  // mean of the heaviest mode.
  struct Cluster {
    double x, y, theta, w, sx, sy, sc, ss;
  };
  std::vector<Cluster> cl;
  for (const Particle& p : particles_) {
    Cluster* hit = nullptr;
    for (Cluster& c : cl)
      if (sq(p.x - c.x) + sq(p.y - c.y) < sq(700.0) && std::fabs(wrapAngle(p.theta - c.theta)) < 0.7) {
        hit = &c;
        break;
      }
    if (!hit) {
      if (cl.size() >= 30) continue;
      cl.push_back({p.x, p.y, p.theta, 0, 0, 0, 0, 0});
      hit = &cl.back();
    }
    hit->w += p.w;
    hit->sx += p.w * p.x;
    hit->sy += p.w * p.y;
    hit->sc += p.w * std::cos(p.theta);
    hit->ss += p.w * std::sin(p.theta);
  }
  double total = 0;
  for (const Particle& p : particles_) total += p.w;
  const Cluster* best = nullptr;
  int modes = 0;
  modes_.clear();
  for (const Cluster& c : cl) {
    if (c.w > 0) modes_.push_back({c.sx / c.w, c.sy / c.w, c.w / total});
    if (c.w > 0.05 * total) ++modes;
    if (!best || c.w > best->w) best = &c;
  }
  blackboard::LocalisationEstimate e = estimate_;
  e.time = time;
  e.hypotheses = modes;
  e.jumped = false;
  if (best && best->w > 0) {
    e.pose.x = best->sx / best->w;
    e.pose.y = best->sy / best->w;
    e.pose.theta = std::atan2(best->ss, best->sc);
    double vx = 0, vy = 0;
    for (const Particle& p : particles_)
      if (sq(p.x - best->x) + sq(p.y - best->y) < sq(700.0) && std::fabs(wrapAngle(p.theta - best->theta)) < 0.7) {
        vx += p.w * sq(p.x - e.pose.x);
        vy += p.w * sq(p.y - e.pose.y);
      }
    e.sd_x = std::sqrt(vx / best->w);
    e.sd_y = std::sqrt(vy / best->w);
    e.sd_theta = std::sqrt(std::max(0.0, -2.0 * std::log(std::hypot(best->sc, best->ss) / best->w)));
  }
  e.confidence = std::clamp(w_fast_, 0.0, 1.0);
  if (have_estimate_) {
    // Where the previous estimate would be after this frame's odometry.
    const blackboard::FieldPose& o = estimate_.pose;
    const double mid = o.theta + 0.5 * turn;
    const double px = o.x + std::cos(mid) * forward - std::sin(mid) * left;
    const double py = o.y + std::sin(mid) * forward + std::cos(mid) * left;
    if (std::hypot(e.pose.x - px, e.pose.y - py) > cfg_.jump_distance ||
        std::fabs(wrapAngle(e.pose.theta - (o.theta + turn))) > cfg_.jump_angle) {
      e.jumped = true;
      ++e.jumps;
      e.jump_time = time;
    }
  }
  have_estimate_ = true;
  estimate_ = e;
}

}  // namespace agent::localisation
