#include "sim/vision/VisionOracle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/nao/NaoFacts.hpp"
#include "common/random/DeriveSeed.hpp"
#include "sim/sensors/Noise.hpp"

namespace simswift::vision {

namespace al = common::libagent;

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr int kCircleSamples = 32;

// Vision streams sit apart from the sensor StreamIds (sim/sensors/Noise.hpp)
// so that appending sensors never renumbers them.
constexpr auto kVisionStream = static_cast<sensors::StreamId>(0x5649u);       // per (robot, camera, frame)
constexpr auto kVisionCalibStream = static_cast<sensors::StreamId>(0x5643u);  // once per robot

// A counter-based random sequence: draw k is splitmix64(key, k). Seeding is free,
// so every object gets its own sequence and its draws do not depend on how
// many other objects were seen before it.
class Draws {
 public:
  explicit Draws(uint64_t key) : key_(key) {}
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double gaussian() {  // Box-Muller, one value per pair (simple and stateless)
    const double u1 = 1.0 - uniform();  // (0, 1]
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
  }

 private:
  uint64_t next() { return common::random::splitmix64(key_ ^ common::random::splitmix64(++n_)); }
  uint64_t key_;
  uint64_t n_ = 0;
};

double wrap(double a) { return std::remainder(a, 2.0 * M_PI); }

// Output priority of an observation (kMaxObservations may cut the tail).
int priority(al::ObservationType t) {
  switch (t) {
    case al::ObservationType::Ball: return 0;
    case al::ObservationType::GoalPost: return 1;
    case al::ObservationType::Robot: return 2;
    case al::ObservationType::PenaltyCross: return 3;
    case al::ObservationType::CentreCircle: return 4;
    case al::ObservationType::LineCorner: return 5;
    case al::ObservationType::FieldLine: return 6;
  }
  return 7;
}

al::ObservationType typeOf(Feature f) {
  switch (f) {
    case Feature::Ball: return al::ObservationType::Ball;
    case Feature::GoalPost: return al::ObservationType::GoalPost;
    case Feature::Robot: return al::ObservationType::Robot;
    case Feature::PenaltyMark: return al::ObservationType::PenaltyCross;
    case Feature::CentreCircle: return al::ObservationType::CentreCircle;
    case Feature::Corner: return al::ObservationType::LineCorner;
    case Feature::Line: return al::ObservationType::FieldLine;
  }
  return al::ObservationType::Ball;
}

double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double l2 = d.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

// Segment [from, from + len * dir] against an axis-aligned box (slab test).
bool segmentHitsBox(const Eigen::Vector3d& from, const Eigen::Vector3d& dir, double len, const Eigen::AlignedBox3d& box) {
  double t0 = 0, t1 = len;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(dir[k]) < 1e-12) {
      if (from[k] < box.min()[k] || from[k] > box.max()[k]) return false;
      continue;
    }
    double a = (box.min()[k] - from[k]) / dir[k], b = (box.max()[k] - from[k]) / dir[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

Eigen::Vector2d xy(const Eigen::Vector3d& v) { return {v.x(), v.y()}; }

int headLinkOf(const RobotModel& m) {
  const int j = m.jointIndex("HeadPitch");
  if (j < 0) throw std::runtime_error("vision: the robot model has no HeadPitch joint to carry the cameras");
  return m.joints()[j].child_link;
}

}  // namespace

Eigen::Vector2d GroundFrame::toRobot(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d d = p - origin;
  return {cos_h * d.x() + sin_h * d.y(), -sin_h * d.x() + cos_h * d.y()};
}

CameraMount cameraMount(int camera) {
  // The NAO's hardware facts (common/nao/NaoFacts.hpp: mm from the
  // HeadPitch frame, rad down; the V5's and the V6's are the same), in m.
  if (camera != 0 && camera != 1) throw std::invalid_argument("vision: camera must be 0 (top) or 1 (bottom)");
  const common::nao::CameraMount& m =
      common::nao::cameraMount(camera == 0 ? common::nao::Camera::Top : common::nao::Camera::Bottom);
  return {Eigen::Vector3d(m.x, m.y, m.z) / 1000.0, m.pitch_down};  // mm -> m (exact for these four)
}

VisionOracle::VisionOracle(const FieldConfig& field, VisionConfig config, uint64_t seed)
    : features_(FieldFeatures::fromField(field)),
      config_(std::move(config)),
      seed_(seed),
      // Unset: the V5's lens (the runner sets a V6 run's: sim/runner/Bodies.hpp).
      tan_half_h_(std::tan(config_.hfov_deg.value_or(common::nao::kV5CameraLens.horizontal_fov / kDeg) * kDeg / 2)),
      tan_half_v_(std::tan(config_.vfov_deg.value_or(common::nao::kV5CameraLens.vertical_fov / kDeg) * kDeg / 2)),
      ball_radius_(field.ball.diameter / 2),
      line_half_width_(field.line_width / 2) {
  margin_ = std::max(1e-4, config_.occlusion_margin_mm * 1e-3);
  sight_ = dCreateCapsule(nullptr, margin_, 1.0);
}

VisionOracle::~VisionOracle() {
  if (sight_) dGeomDestroy(sight_);
}

void VisionOracle::setTeams(std::vector<int> team_of_robot, std::vector<int> colour_of_robot) {
  teams_ = std::move(team_of_robot);
  colours_ = std::move(colour_of_robot);
}

Eigen::Isometry3d VisionOracle::cameraPose(const World& world, int robot, int camera) const {
  const RobotBody& body = world.robot(robot);
  const CameraMount m = cameraMount(camera);
  Eigen::Isometry3d mount = Eigen::Isometry3d::Identity();
  mount.translation() = m.offset;
  mount.linear() = Eigen::AngleAxisd(m.pitch_down, Eigen::Vector3d::UnitY()).toRotationMatrix();  // +y tips x down
  return body.linkPose(headLinkOf(body.model())) * mount;
}

GroundFrame VisionOracle::groundFrame(const World& world, int robot) const {
  const RobotBody& body = world.robot(robot);
  const RobotModel& m = body.model();
  const int lf = m.linkIndex("LFoot"), rf = m.linkIndex("RFoot");
  const Eigen::Isometry3d torso = body.linkPose(m.rootLink());
  const Eigen::Vector2d origin = (lf >= 0 && rf >= 0) ? Eigen::Vector2d(0.5 * (xy(body.linkPose(lf).translation()) +
                                                                               xy(body.linkPose(rf).translation())))
                                                      : xy(torso.translation());
  const Eigen::Vector3d fwd = torso.linear().col(0);
  return GroundFrame(origin, std::atan2(fwd.y(), fwd.x()));
}

bool VisionOracle::blind(const World& world, int robot) const {
  const RobotBody& body = world.robot(robot);
  const Eigen::Isometry3d torso = body.linkPose(body.model().rootLink());
  const double tilt = std::acos(std::clamp(torso.linear()(2, 2), -1.0, 1.0));  // torso z from vertical
  if (tilt > config_.lying_tilt_deg * kDeg) return true;
  const double rate = body.linkAngularVelocity(body.model().rootLink()).norm();
  return tilt > config_.falling_tilt_deg * kDeg && rate > config_.falling_rate_dps * kDeg;
}

bool VisionOracle::inView(const Eigen::Isometry3d& to_cam, const Eigen::Vector3d& p) const {
  const Eigen::Vector3d q = to_cam * p;  // camera frame: x along the optical axis
  return q.x() > 1e-3 && std::abs(q.y()) <= tan_half_h_ * q.x() && std::abs(q.z()) <= tan_half_v_ * q.x();
}

void VisionOracle::refreshBounds(const World& world) {
  if (bounds_tick_ == world.tick() && static_cast<int>(bounds_.size()) == world.numRobots()) return;
  bounds_tick_ = world.tick();
  bounds_.assign(world.numRobots(), Eigen::AlignedBox3d());
  for (int i = 0; i < world.numRobots(); ++i)
    for (dGeomID g : world.robot(i).geoms()) {
      dReal a[6];
      dGeomGetAABB(g, a);
      bounds_[i].extend(Eigen::Vector3d(a[0], a[2], a[4]));
      bounds_[i].extend(Eigen::Vector3d(a[1], a[3], a[5]));
    }
}

bool VisionOracle::occluded(const World& world, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                            double stop_short, int ignore_a, int ignore_b, int ignore_post) {
  const Eigen::Vector3d d = to - from;
  const double full = d.norm();
  const double len = full - stop_short;
  if (len <= 1e-6) return false;
  const Eigen::Vector3d dir = d / full;
  // Goal posts: vertical cylinders from the ground to the crossbar.
  for (int k = 0; k < static_cast<int>(features_.posts.size()); ++k) {
    if (k == ignore_post) continue;
    FieldPost p = features_.posts[k];
    p.radius += margin_;
    const Eigen::Vector2d m = xy(from) - p.at, v = xy(dir);
    const double A = v.squaredNorm();
    if (A < 1e-12) continue;
    const double B = 2 * m.dot(v), C = m.squaredNorm() - p.radius * p.radius;
    const double disc = B * B - 4 * A * C;
    if (disc < 0) continue;
    const double t = (-B - std::sqrt(disc)) / (2 * A);  // entry
    if (t <= 0 || t >= len) continue;
    const double z = from.z() + t * dir.z();
    if (z >= 0 && z <= p.height) return true;
  }
  // Robots: their bounds first, then ODE's collider against each geom with
  // a thin capsule along the line of sight (the "fat ray"; with a plain ray
  // the line of sight would slip through the gaps of the slim collision
  // model, e.g. between the legs).
  refreshBounds(world);
  const double m = margin_;
  const double L = len - m;  // capsule core length: the end cap reaches len
  if (L <= 0) return false;
  bool placed = false;
  for (int i = 0; i < world.numRobots(); ++i) {
    if (i == ignore_a || i == ignore_b) continue;
    Eigen::AlignedBox3d box = bounds_[i];
    box.min().array() -= m;
    box.max().array() += m;
    if (!segmentHitsBox(from, dir, len, box)) continue;
    if (!placed) {
      const Eigen::Vector3d mid = from + dir * (L / 2);
      const Eigen::Matrix3d R = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), dir).toRotationMatrix();
      dMatrix3 r;
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) r[4 * a + b] = R(a, b);
        r[4 * a + 3] = 0;
      }
      dGeomCapsuleSetParams(sight_, m, L);
      dGeomSetPosition(sight_, mid.x(), mid.y(), mid.z());
      dGeomSetRotation(sight_, r);
      placed = true;
    }
    for (dGeomID g : world.robot(i).geoms()) {
      dContactGeom c;
      if (dCollide(sight_, g, 1, &c, sizeof c) > 0) return true;
    }
  }
  return false;
}

std::vector<SeenObject> VisionOracle::observe(const World& world, int robot, int64_t frame) {
  if (robot < 0 || robot >= world.numRobots())
    throw std::out_of_range("VisionOracle::observe: no robot " + std::to_string(robot));
  std::vector<SeenObject> out;
  if (!config_.enabled || blind(world, robot)) return out;
  for (int cam = 0; cam < 2; ++cam) observeCamera(world, robot, cam, frame, out);
  if (config_.ball_model == BallModel::Thesis2017) observeThesisBall(world, robot, out);
  return out;
}

// The thesis's simulated ball detection (rUNSWift 2018 SimVisionAdapter):
// the true ball, exact, when within the ball range of the robot and within
// +-thesis_ball_half_angle_deg of the camera's heading on the ground; no
// vertical test, no occlusion, no misses. Reported once (top camera).
void VisionOracle::observeThesisBall(const World& world, int robot, std::vector<SeenObject>& out) const {
  if (!world.hasBall() || !config_[Feature::Ball].enabled) return;
  const GroundFrame g = groundFrame(world, robot);
  const Eigen::Isometry3d cam = cameraPose(world, robot, 0);
  const Eigen::Vector3d axis = cam.linear().col(0);
  const Eigen::Vector2d ball = xy(world.ballPosition());
  const Eigen::Vector2d from_eye = ball - xy(cam.translation());
  const double off_axis = std::abs(wrap(std::atan2(from_eye.y(), from_eye.x()) - std::atan2(axis.y(), axis.x())));
  const Eigen::Vector2d rel = g.toRobot(ball);  // m, robot frame
  const DetectorSpec& s = config_[Feature::Ball];
  if (off_axis > config_.thesis_ball_half_angle_deg * kDeg || rel.norm() * 1000 > s.max_distance_mm ||
      rel.norm() * 1000 < s.min_distance_mm)
    return;
  SeenObject o;
  o.obs = al::Observation{};
  o.obs.type = al::ObservationType::Ball;
  o.obs.camera = 0;
  o.obs.x = static_cast<float>(rel.x() * 1000);
  o.obs.y = static_cast<float>(rel.y() * 1000);
  o.obs.distance = static_cast<float>(rel.norm() * 1000);
  o.obs.heading = static_cast<float>(std::atan2(rel.y(), rel.x()));
  o.obs.team = -1;
  o.obs.colour = -1;
  o.obs.corner = al::CornerKind::None;
  o.obs.confidence = 1.0f;
  out.push_back(o);
}

int VisionOracle::fill(const World& world, int robot, al::CameraFrame& frame) {
  std::vector<SeenObject> seen = observe(world, robot, frame.frame_index);
  std::stable_sort(seen.begin(), seen.end(), [](const SeenObject& a, const SeenObject& b) {
    return priority(a.obs.type) < priority(b.obs.type);
  });
  const int n = std::min<int>(static_cast<int>(seen.size()), al::kMaxObservations);
  for (int i = 0; i < n; ++i) frame.observations[i] = seen[i].obs;
  frame.num_observations = n;
  if (robot >= static_cast<int>(sightings_.size())) sightings_.resize(robot + 1);
  for (int i = 0; i < n; ++i) {
    if (seen[i].obs.type != al::ObservationType::Ball || seen[i].false_positive) continue;
    BallSighting& b = sightings_[robot];
    if (b.frame != frame.frame_index) {
      // Both cameras may see it in one frame: a frame counts once.
      b.consecutive = b.frame == frame.frame_index - 1 ? b.consecutive + 1 : 1;
      b.distance_mm = seen[i].obs.distance;
    } else if (seen[i].obs.distance < b.distance_mm) {
      b.distance_mm = seen[i].obs.distance;
    }
    b.frame = frame.frame_index;
  }
  const int dropped = static_cast<int>(seen.size()) - n;
  dropped_ += dropped;
  return dropped;
}

// One camera of one robot at one frame: its pose, the robot's ground frame,
// the calibration error and the frame's draws, and the helpers every stage
// shares. Each see*() stage appends the observations of one kind of object.
class VisionOracle::CameraView {
 public:
  CameraView(VisionOracle& oracle, const World& world, int robot, int camera, int64_t frame,
             std::vector<SeenObject>& out);

  void seeBall();
  void seeGoalPosts();
  void seeRobots();
  void seeMarks();
  void seeCentreCircles();
  void seeCorners();
  void seeLines();
  void addPhantoms();  // the detector's false positives (noise only)

 private:
  // This frame's sequence for object `index` of kind `f`.
  Draws drawsFor(Feature f, uint64_t index) const;
  // Robot-relative point (m) with distance and bearing noise; `height` is
  // the camera's height above the object's reference point (m).
  Eigen::Vector2d noisyPoint(const DetectorSpec& s, Eigen::Vector2d rel, double height, Draws& r) const;
  // Appends an observation at rel_m (robot frame, m); returns it for the
  // stage to add what its kind carries.
  SeenObject& emit(Feature f, const Eigen::Vector2d& rel_m, double confidence, int source);
  // A field angle (rad) as seen from the robot, with orientation noise.
  float orient(const DetectorSpec& s, double field_angle, Draws& r) const;
  // Range + image + Bernoulli + occlusion for a point-like object. `look` is
  // the point that must be in the image (field, m), `ground` its ground
  // point. Returns the detection probability, or a negative value if unseen.
  double detect(const DetectorSpec& s, const Eigen::Vector3d& look, const Eigen::Vector2d& ground, double stop_short,
                int ignore_robot, int ignore_post, double factor, Draws& r);
  // The points of line k that can be seen, as runs of the line's fixed
  // sample grid, each reported as a piece.
  void seeLine(const DetectorSpec& s, int k);

  VisionOracle& o_;
  const World& world_;
  const VisionConfig& config_;
  const FieldFeatures& features_;
  const int robot_, camera_;
  const bool noisy_;
  const Eigen::Isometry3d cam_, to_cam_;
  const Eigen::Vector3d eye_;  // camera position (field, m)
  const GroundFrame g_;
  Eigen::Vector2d off_ = Eigen::Vector2d::Zero();  // camera position error (robot frame, m)
  uint64_t frame_key_ = 0;
  std::vector<SeenObject>& out_;
};

VisionOracle::CameraView::CameraView(VisionOracle& oracle, const World& world, int robot, int camera, int64_t frame,
                                     std::vector<SeenObject>& out)
    : o_(oracle),
      world_(world),
      config_(oracle.config_),
      features_(oracle.features_),
      robot_(robot),
      camera_(camera),
      noisy_(oracle.config_.noise),
      cam_(oracle.cameraPose(world, robot, camera)),
      to_cam_(cam_.inverse()),
      eye_(cam_.translation()),
      g_(oracle.groundFrame(world, robot)),
      out_(out) {
  // Camera position error (table 3.1), once per robot, horizontal part: the
  // robot believes its camera `off` away from where it is, so everything it
  // sees is shifted by -off (robot frame, m).
  if (noisy_ && config_.camera_offset_mm > 0) {
    Draws c(sensors::streamSeed(o_.seed_, robot, kVisionCalibStream));
    off_.x() = (2 * c.uniform() - 1) * config_.camera_offset_mm * 1e-3;
    off_.y() = (2 * c.uniform() - 1) * config_.camera_offset_mm * 1e-3;
  }
  frame_key_ = sensors::streamSeed(o_.seed_, robot, kVisionStream);
  frame_key_ = common::random::deriveSeed(frame_key_, static_cast<uint64_t>(camera) + 1);
  frame_key_ = common::random::deriveSeed(frame_key_, static_cast<uint64_t>(frame));
}

Draws VisionOracle::CameraView::drawsFor(Feature f, uint64_t index) const {
  // The tag is hashed so that (feature, index) pairs spread over all 64 bits.
  return Draws(common::random::deriveSeed(frame_key_,
                                          common::random::splitmix64((static_cast<uint64_t>(f) << 40) ^ index)));
}

Eigen::Vector2d VisionOracle::CameraView::noisyPoint(const DetectorSpec& s, Eigen::Vector2d rel, double height,
                                                     Draws& r) const {
  rel -= off_;
  if (!noisy_) return rel;
  const double d = rel.norm();
  const double dc = (xy(eye_) - (g_.origin + Eigen::Rotation2Dd(g_.heading) * rel)).norm();
  const double h = std::max(height, 0.05);
  const double elev = (h * h + dc * dc) / h * s.elevation_sigma_deg * kDeg;
  const double abs_m = s.distance_sigma_mm * 1e-3, rel_m = s.distance_sigma_fraction * d;
  const double sd = std::sqrt(abs_m * abs_m + rel_m * rel_m + elev * elev);
  const double dn = std::max(0.0, d + sd * r.gaussian());
  const double bn = std::atan2(rel.y(), rel.x()) + s.bearing_sigma_deg * kDeg * r.gaussian();
  return Eigen::Vector2d(dn * std::cos(bn), dn * std::sin(bn));
}

SeenObject& VisionOracle::CameraView::emit(Feature f, const Eigen::Vector2d& rel_m, double confidence, int source) {
  SeenObject s;
  al::Observation& o = s.obs;
  o = al::Observation{};
  o.type = typeOf(f);
  o.camera = camera_;
  o.x = static_cast<float>(rel_m.x() * 1000);
  o.y = static_cast<float>(rel_m.y() * 1000);
  o.distance = static_cast<float>(rel_m.norm() * 1000);
  o.heading = static_cast<float>(std::atan2(rel_m.y(), rel_m.x()));
  o.team = -1;
  o.colour = -1;
  o.corner = al::CornerKind::None;
  o.confidence = static_cast<float>(confidence);
  s.source = source;
  out_.push_back(s);
  return out_.back();
}

float VisionOracle::CameraView::orient(const DetectorSpec& s, double field_angle, Draws& r) const {
  double a = field_angle - g_.heading;
  if (noisy_) a += s.orientation_sigma_deg * kDeg * r.gaussian();
  return static_cast<float>(wrap(a));
}

double VisionOracle::CameraView::detect(const DetectorSpec& s, const Eigen::Vector3d& look,
                                        const Eigen::Vector2d& ground, double stop_short, int ignore_robot,
                                        int ignore_post, double factor, Draws& r) {
  if (!s.enabled) return -1;
  const double d_mm = g_.toRobot(ground).norm() * 1000;
  if (d_mm < s.min_distance_mm || d_mm > s.max_distance_mm) return -1;
  if (!o_.inView(to_cam_, look)) return -1;
  const double p = s.probability(d_mm) * factor;
  const double u = r.uniform();  // drawn whether or not it is used: fixed sequence per object
  if (noisy_ && !(u < p)) return -1;
  if (o_.occluded(world_, eye_, look, stop_short, robot_, ignore_robot, ignore_post)) return -1;
  return noisy_ ? p : 1.0;
}

// The ball (none in a `ball: none` world, or with the thesis's ball model).
void VisionOracle::CameraView::seeBall() {
  if (!world_.hasBall() || config_.ball_model != BallModel::Detector) return;
  const DetectorSpec& s = config_[Feature::Ball];
  const Eigen::Vector3d b = world_.ballPosition();
  Draws r = drawsFor(Feature::Ball, 0);
  // On a line: the ball's footprint overlaps a painted band.
  const double ball_radius = o_.ball_radius_;
  bool on_line = false;
  const Eigen::Vector2d bp = xy(b);
  const double reach = o_.line_half_width_ + ball_radius;
  for (const LineSegment& l : features_.lines)
    on_line = on_line || distanceToSegment(bp, {l.ax, l.ay}, {l.bx, l.by}) <= l.width / 2 + ball_radius;
  for (const LineCircle& c : features_.circles)
    on_line = on_line || std::abs((bp - Eigen::Vector2d(c.cx, c.cy)).norm() - c.radius) <= c.width / 2 + ball_radius;
  for (const Eigen::Vector2d& m : features_.marks) on_line = on_line || (bp - m).norm() <= reach + 0.05;
  const double p = detect(s, b, bp, ball_radius, -1, -1, on_line ? s.on_line_factor : 1.0, r);
  if (p >= 0) emit(Feature::Ball, noisyPoint(s, g_.toRobot(bp), eye_.z() - b.z(), r), p, -1);
}

// Goal posts, at their base (what gives a detector the distance).
void VisionOracle::CameraView::seeGoalPosts() {
  const DetectorSpec& s = config_[Feature::GoalPost];
  for (int k = 0; k < static_cast<int>(features_.posts.size()); ++k) {
    const FieldPost& post = features_.posts[k];
    Draws r = drawsFor(Feature::GoalPost, k);
    const Eigen::Vector3d base(post.at.x(), post.at.y(), 0.0);
    if (!s.enabled || !o_.inView(to_cam_, base)) continue;
    const double p = detect(s, base + Eigen::Vector3d(0, 0, 0.05), post.at, 0.0, -1, k, 1.0, r);
    if (p >= 0) emit(Feature::GoalPost, noisyPoint(s, g_.toRobot(post.at), eye_.z(), r), p, k);
  }
}

// Other robots: the torso must be in the image; reported at the feet.
void VisionOracle::CameraView::seeRobots() {
  const DetectorSpec& s = config_[Feature::Robot];
  for (int i = 0; i < world_.numRobots() && s.enabled; ++i) {
    if (i == robot_) continue;
    const RobotBody& other = world_.robot(i);
    const Eigen::Vector3d torso = other.linkPose(other.model().rootLink()).translation();
    const GroundFrame og = o_.groundFrame(world_, i);
    Draws r = drawsFor(Feature::Robot, i);
    const double p = detect(s, torso, og.origin, 0.0, i, -1, 1.0, r);
    if (p < 0) continue;
    SeenObject& o = emit(Feature::Robot, noisyPoint(s, g_.toRobot(og.origin), eye_.z(), r), p, i);
    o.obs.team = i < static_cast<int>(o_.teams_.size()) ? o_.teams_[i] : 0;
    o.obs.colour = i < static_cast<int>(o_.colours_.size()) ? o_.colours_[i] : 0;
    o.obs.orientation = orient(s, og.heading, r);
    const Eigen::Matrix3d R = other.linkPose(other.model().rootLink()).linear();
    if (std::acos(std::clamp(R(2, 2), -1.0, 1.0)) > config_.lying_tilt_deg * kDeg)
      o.obs.flags |= al::kObservationRobotFallen;
  }
}

// Penalty marks and the centre mark.
void VisionOracle::CameraView::seeMarks() {
  const DetectorSpec& s = config_[Feature::PenaltyMark];
  for (int k = 0; k < static_cast<int>(features_.marks.size()); ++k) {
    const Eigen::Vector2d& m = features_.marks[k];
    Draws r = drawsFor(Feature::PenaltyMark, k);
    const double p = detect(s, {m.x(), m.y(), 0.0}, m, 0.02, -1, -1, 1.0, r);
    if (p >= 0) emit(Feature::PenaltyMark, noisyPoint(s, g_.toRobot(m), eye_.z(), r), p, k);
  }
}

// The centre circle: enough of the band in view and unoccluded; reported at its centre.
void VisionOracle::CameraView::seeCentreCircles() {
  const DetectorSpec& s = config_[Feature::CentreCircle];
  for (int k = 0; k < static_cast<int>(features_.circles.size()) && s.enabled; ++k) {
    const LineCircle& c = features_.circles[k];
    const Eigen::Vector2d centre(c.cx, c.cy);
    int visible = 0;
    for (int i = 0; i < kCircleSamples; ++i) {
      const double a = 2 * M_PI * i / kCircleSamples;
      const Eigen::Vector3d q(c.cx + c.radius * std::cos(a), c.cy + c.radius * std::sin(a), 0.0);
      const double d_mm = g_.toRobot(xy(q)).norm() * 1000;
      if (d_mm >= s.min_distance_mm && d_mm <= s.max_distance_mm && o_.inView(to_cam_, q) &&
          !o_.occluded(world_, eye_, q, 0.02, robot_, -1, -1))
        ++visible;
    }
    if (visible < config_.circle_min_fraction * kCircleSamples || visible == 0) continue;
    Draws r = drawsFor(Feature::CentreCircle, k);
    const double d_mm = g_.toRobot(centre).norm() * 1000;
    if (d_mm < s.min_distance_mm || d_mm > s.max_distance_mm) continue;
    const double p = s.probability(d_mm);
    if (noisy_ && !(r.uniform() < p)) continue;
    // Orientation: along a line through the centre (the halfway line).
    double along = M_PI / 2;
    for (const LineSegment& l : features_.lines)
      if (distanceToSegment(centre, {l.ax, l.ay}, {l.bx, l.by}) < 0.01) along = std::atan2(l.by - l.ay, l.bx - l.ax);
    SeenObject& o = emit(Feature::CentreCircle, noisyPoint(s, g_.toRobot(centre), eye_.z(), r), noisy_ ? p : 1.0, k);
    o.obs.orientation = orient(s, along, r);
  }
}

// Line intersections (L, T, X), with their kind and orientation.
void VisionOracle::CameraView::seeCorners() {
  const DetectorSpec& s = config_[Feature::Corner];
  for (int k = 0; k < static_cast<int>(features_.corners.size()) && s.enabled; ++k) {
    const FieldCorner& c = features_.corners[k];
    Draws r = drawsFor(Feature::Corner, k);
    const double p = detect(s, {c.at.x(), c.at.y(), 0.0}, c.at, 0.02, -1, -1, 1.0, r);
    if (p < 0) continue;
    SeenObject& o = emit(Feature::Corner, noisyPoint(s, g_.toRobot(c.at), eye_.z(), r), p, k);
    o.obs.corner = c.kind;
    o.obs.orientation = orient(s, c.orientation, r);
  }
}

// Lines: test points every line_step_mm; each run of visible points is a piece.
void VisionOracle::CameraView::seeLines() {
  const DetectorSpec& s = config_[Feature::Line];
  for (int k = 0; k < static_cast<int>(features_.lines.size()) && s.enabled; ++k) seeLine(s, k);
}

void VisionOracle::CameraView::seeLine(const DetectorSpec& s, int k) {
  const double step = config_.line_step_mm * 1e-3;
  const LineSegment& l = features_.lines[k];
  const Eigen::Vector2d a(l.ax, l.ay), b(l.bx, l.by);
  const int n = std::max(2, static_cast<int>(std::ceil((b - a).norm() / step)) + 1);
  // Only the part of the line within max_distance of the feet can be
  // seen: sample the fixed grid there (same points as sampling it all).
  const Eigen::Vector2d dv = b - a, m = a - g_.origin;
  const double R = s.max_distance_mm * 1e-3;
  const double A = dv.squaredNorm(), B = 2 * m.dot(dv), C = m.squaredNorm() - R * R;
  const double disc = B * B - 4 * A * C;
  if (disc <= 0) return;
  const double t0 = (-B - std::sqrt(disc)) / (2 * A), t1 = (-B + std::sqrt(disc)) / (2 * A);
  if (t1 < 0 || t0 > 1) return;
  const int i0 = std::max(0, static_cast<int>(std::floor(t0 * (n - 1))));
  const int i1 = std::min(n - 1, static_cast<int>(std::ceil(t1 * (n - 1))));
  int run_start = -1, piece = 0;
  double run_near = 1e18;
  for (int i = i0; i <= i1 + 1; ++i) {
    bool vis = false;
    double d_mm = 0;
    Eigen::Vector2d q;
    if (i <= i1) {
      q = a + (b - a) * (static_cast<double>(i) / (n - 1));
      d_mm = g_.toRobot(q).norm() * 1000;
      vis = d_mm >= s.min_distance_mm && d_mm <= s.max_distance_mm && o_.inView(to_cam_, {q.x(), q.y(), 0.0}) &&
            !o_.occluded(world_, eye_, {q.x(), q.y(), 0.0}, 0.02, robot_, -1, -1);
    }
    if (vis) {
      if (run_start < 0) run_start = i, run_near = 1e18;
      run_near = std::min(run_near, d_mm);
      continue;
    }
    if (run_start < 0) continue;
    // A run ended at i - 1.
    const Eigen::Vector2d p0 = a + (b - a) * (static_cast<double>(run_start) / (n - 1));
    const Eigen::Vector2d p1 = a + (b - a) * (static_cast<double>(i - 1) / (n - 1));
    run_start = -1;
    if ((p1 - p0).norm() * 1000 < config_.min_line_mm) continue;
    Draws r = drawsFor(Feature::Line, (static_cast<uint64_t>(k) << 16) | static_cast<uint64_t>(piece++));
    const double p = s.probability(run_near);
    if (noisy_ && !(r.uniform() < p)) continue;
    const Eigen::Vector2d e0 = noisyPoint(s, g_.toRobot(p0), eye_.z(), r);
    const Eigen::Vector2d e1 = noisyPoint(s, g_.toRobot(p1), eye_.z(), r);
    // Distance and heading of the nearest point of the piece seen.
    const Eigen::Vector2d d = e1 - e0;
    const double t = d.squaredNorm() > 0 ? std::clamp(-e0.dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    SeenObject& o = emit(Feature::Line, e0, noisy_ ? p : 1.0, k);
    const Eigen::Vector2d near = e0 + t * d;
    o.obs.distance = static_cast<float>(near.norm() * 1000);
    o.obs.heading = static_cast<float>(std::atan2(near.y(), near.x()));
    o.obs.x2 = static_cast<float>(e1.x() * 1000);
    o.obs.y2 = static_cast<float>(e1.y() * 1000);
    o.obs.orientation = static_cast<float>(std::atan2(d.y(), d.x()));
  }
}

// False positives: per kind, a phantom at a random ground point this camera
// sees within the detector's range (32 random pixels tried).
void VisionOracle::CameraView::addPhantoms() {
  for (int fi = 0; fi < kNumFeatures; ++fi) {
    const Feature f = static_cast<Feature>(fi);
    const DetectorSpec& s = config_[f];
    if (!s.enabled || s.false_positive_rate <= 0) continue;
    Draws r = drawsFor(f, 0xFFFFFFull);
    if (!(r.uniform() < s.false_positive_rate)) continue;
    for (int attempt = 0; attempt < 32; ++attempt) {
      const Eigen::Vector3d ray = cam_.linear() * Eigen::Vector3d(1.0, o_.tan_half_h_ * (2 * r.uniform() - 1),
                                                                  o_.tan_half_v_ * (2 * r.uniform() - 1));
      if (ray.z() > -1e-6) continue;  // above the horizon
      const Eigen::Vector3d hit = eye_ + (-eye_.z() / ray.z()) * ray;
      const Eigen::Vector2d rel = g_.toRobot(xy(hit)) - off_;
      const double d_mm = rel.norm() * 1000;
      if (d_mm < s.min_distance_mm || d_mm > s.max_distance_mm) continue;
      SeenObject& o = emit(f, rel, r.uniform() * s.p_near, -1);
      o.false_positive = true;
      o.obs.orientation = static_cast<float>(wrap(2 * M_PI * r.uniform()));
      if (f == Feature::Robot) {  // a phantom in one of the two jerseys
        o.obs.colour = r.uniform() < 0.5 ? 0 : 1;
        o.obs.team = -1;
        for (size_t i = 0; i < o_.teams_.size() && i < o_.colours_.size(); ++i)
          if (o_.colours_[i] == o.obs.colour) o.obs.team = o_.teams_[i];
      }
      if (f == Feature::Corner) o.obs.corner = static_cast<al::CornerKind>(1 + static_cast<int>(r.uniform() * 3));
      if (f == Feature::Line) {
        const double len = std::max(config_.min_line_mm, 1000 * r.uniform()) * 1e-3;
        const Eigen::Vector2d e1 = rel + len * Eigen::Vector2d(std::cos(o.obs.orientation), std::sin(o.obs.orientation));
        o.obs.x2 = static_cast<float>(e1.x() * 1000);
        o.obs.y2 = static_cast<float>(e1.y() * 1000);
      }
      break;
    }
  }
}

// One camera's observations, stage by stage in this fixed order: ball, goal
// posts, robots, marks, centre circle, corners, lines, then the phantoms.
// Every object draws from its own sequence (drawsFor), so no stage's draws
// depend on another's; the order fixes the order of the observations (which
// observe() returns and fill()'s stable sort keeps within a kind).
void VisionOracle::observeCamera(const World& world, int robot, int camera, int64_t frame,
                                 std::vector<SeenObject>& out) {
  CameraView view(*this, world, robot, camera, frame, out);
  view.seeBall();
  view.seeGoalPosts();
  view.seeRobots();
  view.seeMarks();
  view.seeCentreCircles();
  view.seeCorners();
  view.seeLines();
  if (config_.noise) view.addPhantoms();
}

}  // namespace simswift::vision
