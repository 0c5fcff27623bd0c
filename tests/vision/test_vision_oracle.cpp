// The vision oracle and its detector model (sim/vision): field of view and
// distance limits, occlusion, noise statistics, false-positive and on-line
// rates, determinism, blindness while lying, the `vision:` scenario block,
// and observations reaching a Perception thread through the runner.
//
// Robots are placed standing (no physics step needed: the oracle reads link
// poses), so every figure here is exact geometry plus the seeded model.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

#include "agent/program/Postures.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/vision/VisionOracle.hpp"
#include "sim/world/ConfigError.hpp"
#include "tests/support/ConfigErrors.hpp"
#ifdef SIMSWIFT_HAVE_CAMERAS
#include "sim/camera/CameraModel.hpp"
#endif

namespace {

using namespace simswift;
using namespace simswift::vision;
namespace al = common::libagent;
constexpr double kDeg = M_PI / 180.0;

std::shared_ptr<const RobotModel> model() {
  static auto m = std::make_shared<const RobotModel>(RobotModel::loadUrdf(SIMSWIFT_SOURCE_DIR "/models/nao_v5.urdf"));
  return m;
}
std::vector<double> stand() {
  return simswift::NaoBinding(*model()).posture(agent::program::postureAngles(agent::program::Posture::Stand));
}

// Noise off: exact positions, no misses, no phantoms, no camera error.
VisionConfig exact() {
  VisionConfig c;
  c.noise = false;
  return c;
}

std::vector<SeenObject> ofType(const std::vector<SeenObject>& v, al::ObservationType t, int camera = -1) {
  std::vector<SeenObject> out;
  for (const SeenObject& s : v)
    if (s.obs.type == t && (camera < 0 || s.obs.camera == camera)) out.push_back(s);
  return out;
}

// Ball centre on the ray from camera `cam` of robot 0 along camera-frame
// direction (1, ty, tz), where it meets the plane z = ball radius.
Eigen::Vector2d ballAlong(const VisionOracle& o, const World& w, int cam, double ty, double tz) {
  const Eigen::Isometry3d pose = o.cameraPose(w, 0, cam);
  const Eigen::Vector3d d = pose.linear() * Eigen::Vector3d(1, ty, tz);
  const double r = w.field().ball.diameter / 2;
  EXPECT_LT(d.z(), 0) << "ray must point down";
  const Eigen::Vector3d p = pose.translation() + (r - pose.translation().z()) / d.z() * d;
  return {p.x(), p.y()};
}

TEST(VisionObservation, SharedStructIsPlainData) {
  static_assert(std::is_trivially_copyable_v<al::Observation>);
  static_assert(std::is_standard_layout_v<al::Observation>);
  static_assert(std::is_trivially_copyable_v<al::CameraFrame>);
  SUCCEED();
}

TEST(VisionConfig, DefaultsFollowTheThesis) {
  const VisionConfig c;
  const DetectorSpec& b = c[Feature::Ball];
  EXPECT_DOUBLE_EQ(b.max_distance_mm, 2500);            // thesis section 3.3.1.1
  EXPECT_DOUBLE_EQ(b.bearing_sigma_deg, 0.1225);        // table 3.1
  EXPECT_DOUBLE_EQ(b.elevation_sigma_deg, 0.1480);
  EXPECT_DOUBLE_EQ(b.distance_sigma_fraction, 0.000965);
  EXPECT_DOUBLE_EQ(c.camera_offset_mm, 5);
  EXPECT_FALSE(c.hfov_deg.has_value());  // the robot's own lens (the runner sets it)
  EXPECT_FALSE(c.vfov_deg.has_value());
  EXPECT_LT(b.on_line_factor, 1.0);
  // Probability: flat, then falling linearly, zero beyond the range.
  EXPECT_DOUBLE_EQ(b.probability(1000), b.p_near);
  EXPECT_NEAR(b.probability(2000), 0.5 * (b.p_near + b.p_at_max), 1e-12);
  EXPECT_DOUBLE_EQ(b.probability(2501), 0.0);
}

TEST(VisionConfig, ScenarioBlockIsReadAndCheckedWithFileLineAndKey) {
  const runner::Scenario sc = runner::Scenario::parse(
      "vision:\n"
      "  noise: off\n"
      "  ball: {max_distance_mm: 3000, false_positive_rate: 0.05, on_line_factor: 0.4}\n"
      "  robots: {enabled: off}\n"
      "robots:\n  - {team: 0, player: 1}\n",
      "v.yaml");
  EXPECT_FALSE(sc.vision.noise);
  EXPECT_DOUBLE_EQ(sc.vision[Feature::Ball].max_distance_mm, 3000);
  EXPECT_DOUBLE_EQ(sc.vision[Feature::Ball].falloff_start_mm, 1500);
  EXPECT_DOUBLE_EQ(sc.vision[Feature::Ball].false_positive_rate, 0.05);
  EXPECT_DOUBLE_EQ(sc.vision[Feature::Ball].on_line_factor, 0.4);
  EXPECT_FALSE(sc.vision[Feature::Robot].enabled);
  EXPECT_TRUE(sc.vision[Feature::GoalPost].enabled);

  EXPECT_FALSE(runner::Scenario::parse("vision: off\nrobots:\n  - {team: 0, player: 1}\n", "v.yaml").vision.enabled);
  EXPECT_TRUE(runner::Scenario::parse("robots:\n  - {team: 0, player: 1}\n", "v.yaml").vision.enabled);

  auto error = [](const std::string& yaml) {
    return simswift::testing::configError(
        [&] { runner::Scenario::parse(yaml + "robots:\n  - {team: 0, player: 1}\n", "bad.yaml"); });
  };
  EXPECT_NE(error("vision:\n  ball:\n    max_distance_mm: -5\n").find("bad.yaml:3: vision.ball.max_distance_mm"),
            std::string::npos);
  EXPECT_NE(error("vision:\n  lines: {p_near: 1.5}\n").find("vision.lines.p_near: must be"), std::string::npos);
  EXPECT_NE(error("vision:\n  ball: {falloff_start_mm: 4000}\n").find("vision.ball.falloff_start_mm"),
            std::string::npos);
  EXPECT_NE(error("vision:\n  bal: {max_distance_mm: 100}\n").find("bad.yaml:2: unknown key 'bal' in vision"), std::string::npos);
  // on_line_factor belongs to the ball only.
  EXPECT_NE(error("vision:\n  robots: {on_line_factor: 0.5}\n").find("unknown key 'on_line_factor' in vision.robots"),
            std::string::npos);
}

TEST(VisionFieldFeatures, Spl2017IntersectionsAndOrientations) {
  const FieldFeatures f = FieldFeatures::fromField(FieldConfig::spl2017());
  int l = 0, t = 0, x = 0;
  for (const FieldCorner& c : f.corners) {
    l += c.kind == al::CornerKind::L;
    t += c.kind == al::CornerKind::T;
    x += c.kind == al::CornerKind::X;
  }
  EXPECT_EQ(l, 8);  // 4 field corners, 4 penalty-area corners
  EXPECT_EQ(t, 6);  // 4 penalty-area sides on the goal lines, 2 halfway line ends
  EXPECT_EQ(x, 2);  // halfway line through the centre circle
  EXPECT_EQ(f.posts.size(), 4u);
  EXPECT_EQ(f.marks.size(), 3u);
  auto at = [&](double px, double py) -> const FieldCorner* {
    for (const FieldCorner& c : f.corners)
      if ((c.at - Eigen::Vector2d(px, py)).norm() < 1e-6) return &c;
    return nullptr;
  };
  ASSERT_NE(at(4.5, 3.0), nullptr);
  EXPECT_EQ(at(4.5, 3.0)->kind, al::CornerKind::L);
  EXPECT_NEAR(at(4.5, 3.0)->orientation, -3 * M_PI / 4, 1e-9);  // into the field
  ASSERT_NE(at(0.0, 3.0), nullptr);
  EXPECT_EQ(at(0.0, 3.0)->kind, al::CornerKind::T);
  EXPECT_NEAR(at(0.0, 3.0)->orientation, -M_PI / 2, 1e-9);  // along the halfway line, into the field
  ASSERT_NE(at(-4.5, 1.1), nullptr);
  EXPECT_EQ(at(-4.5, 1.1)->kind, al::CornerKind::T);
  EXPECT_NEAR(at(-4.5, 1.1)->orientation, 0.0, 1e-9);
  ASSERT_NE(at(0.0, 0.75), nullptr);
  EXPECT_EQ(at(0.0, 0.75)->kind, al::CornerKind::X);
}

#ifdef SIMSWIFT_HAVE_CAMERAS
TEST(VisionOracle, CameraMountMatchesTheRenderer) {
  for (int c = 0; c < 2; ++c) {
    const camera::NaoCameraMount m = camera::naoCameraMount(static_cast<camera::CameraId>(c));
    EXPECT_NEAR((cameraMount(c).offset - m.offset).norm(), 0, 1e-12);
    EXPECT_DOUBLE_EQ(cameraMount(c).pitch_down, m.pitch_down);
  }
}
#endif

class OneRobot : public ::testing::Test {
 protected:
  OneRobot() : world(FieldConfig::spl2017()) { world.addRobot(model(), -1.0, 0.0, 0.0, stand()); }
  World world;
};

// Unset, the oracle's field of view is the V5's 60.9 x 47.6 deg; set (as the
// runner does for a V6 run), the V6's 56.3 x 43.7 deg.
TEST_F(OneRobot, EveryImageEdgeJustInsideAndJustOutside) {
  VisionConfig v6 = exact();
  v6.hfov_deg = 56.3;
  v6.vfov_deg = 43.7;
  struct Lens { VisionConfig config; double hfov_deg, vfov_deg; };
  for (const Lens& lens : {Lens{exact(), 60.9, 47.6}, Lens{v6, 56.3, 43.7}}) {
    SCOPED_TRACE(::testing::Message() << "lens " << lens.hfov_deg << " x " << lens.vfov_deg << " deg");
    VisionOracle o(world.field(), lens.config, 1);
    const double th = std::tan(lens.hfov_deg * kDeg / 2), tv = std::tan(lens.vfov_deg * kDeg / 2);
    const double in = 0.999, out = 1.001;
    for (int cam = 0; cam < 2; ++cam) {
      const Eigen::Isometry3d pose = o.cameraPose(world, 0, cam);
      auto at = [&](double ty, double tz) { return pose * Eigen::Vector3d(2.0, 2.0 * ty, 2.0 * tz); };
      for (double s : {-1.0, 1.0}) {
        EXPECT_TRUE(o.inImage(pose, at(s * th * in, 0))) << "cam " << cam << " side " << s;
        EXPECT_FALSE(o.inImage(pose, at(s * th * out, 0))) << "cam " << cam << " side " << s;
        EXPECT_TRUE(o.inImage(pose, at(0, s * tv * in))) << "cam " << cam << " up/down " << s;
        EXPECT_FALSE(o.inImage(pose, at(0, s * tv * out))) << "cam " << cam << " up/down " << s;
      }
      EXPECT_FALSE(o.inImage(pose, pose * Eigen::Vector3d(-1, 0, 0)));  // behind
    }
  }
}

TEST_F(OneRobot, BallJustInsideAndJustOutsideTheFieldOfView) {
  VisionOracle o(world.field(), exact(), 1);
  const double th = std::tan(60.9 * kDeg / 2), tv = std::tan(47.6 * kDeg / 2);
  struct Edge {
    int cam;
    double ty, tz;  // camera-frame direction at the edge (x = 1)
    const char* what;
  };
  // Side edges at a downward angle that puts the ball on the carpet within
  // range; bottom edge of both cameras; top edge of the bottom camera (the
  // top camera's top edge looks above the horizon: covered by inImage above).
  const std::vector<Edge> edges = {{0, th, -0.35, "top cam left"},    {0, -th, -0.35, "top cam right"},
                                   {0, 0, -tv, "top cam bottom"},     {1, th, -0.2, "bottom cam left"},
                                   {1, -th, -0.2, "bottom cam right"}, {1, 0, -tv, "bottom cam bottom"},
                                   {1, 0, tv, "bottom cam top"}};
  for (const Edge& e : edges) {
    for (double scale : {0.995, 1.005}) {
      const bool side = e.ty != 0;
      const Eigen::Vector2d b = ballAlong(o, world, e.cam, side ? e.ty * scale : 0, side ? e.tz : e.tz * scale);
      world.placeBall(b.x(), b.y());
      const auto seen = ofType(o.observe(world, 0, 0), al::ObservationType::Ball, e.cam);
      EXPECT_EQ(seen.size(), scale < 1 ? 1u : 0u) << e.what << (scale < 1 ? " just inside" : " just outside");
      if (!seen.empty()) {  // exact: the reported point is the ball's, robot-relative
        const Eigen::Vector2d rel = o.groundFrame(world, 0).toRobot(b) * 1000;
        EXPECT_NEAR(seen[0].obs.x, rel.x(), 0.5);
        EXPECT_NEAR(seen[0].obs.y, rel.y(), 0.5);
        EXPECT_NEAR(seen[0].obs.distance, rel.norm(), 0.5);
        EXPECT_NEAR(seen[0].obs.heading, std::atan2(rel.y(), rel.x()), 1e-4);
      }
    }
  }
}

TEST_F(OneRobot, NoBallWorldShowsNoBall) {
  // `ball: none`: a ball 1 m straight ahead is seen; once removed, never.
  VisionOracle o(world.field(), exact(), 1);
  const Eigen::Vector2d ahead = ballAlong(o, world, 1, 0, -0.2);
  world.placeBall(ahead.x(), ahead.y());
  EXPECT_EQ(ofType(o.observe(world, 0, 1), al::ObservationType::Ball, 1).size(), 1u);
  world.removeBall();
  EXPECT_FALSE(world.hasBall());
  EXPECT_TRUE(ofType(o.observe(world, 0, 1), al::ObservationType::Ball, 1).empty());
  EXPECT_THROW(world.placeBall(0, 0), WorldError);
}

TEST_F(OneRobot, BallSightingsCountFramesInARow) {
  // The experiment's found rule counts camera frames in a row that saw the
  // ball (the thesis's controller: 5); a frame without it starts over.
  VisionOracle o(world.field(), exact(), 1);
  const Eigen::Vector2d ahead = ballAlong(o, world, 1, 0, -0.2);
  auto frame = [&](int64_t k) {
    al::CameraFrame f{};
    f.frame_index = k;
    o.fill(world, 0, f);
    return o.ballSighting(0);
  };
  world.placeBall(ahead.x(), ahead.y());
  for (int64_t k = 1; k <= 5; ++k) EXPECT_EQ(frame(k).consecutive, k);
  world.placeBall(-4.0, 2.0);  // behind the robot
  EXPECT_EQ(frame(6).frame, 5);  // the last sighting stays frame 5
  world.placeBall(ahead.x(), ahead.y());
  const auto s = frame(7);
  EXPECT_EQ(s.frame, 7);
  EXPECT_EQ(s.consecutive, 1);
}

TEST_F(OneRobot, Simswift2017PresetSeesTheBallAsTheThesisDid) {
  // vision: {preset: simswift2017}: the ball within 2500 mm and +-30 deg of
  // the camera's heading, with no vertical test and no occlusion.
  VisionConfig c = exact();
  c.ball_model = BallModel::Thesis2017;
  VisionOracle o(world.field(), c, 1);
  const Eigen::Isometry3d cam = o.cameraPose(world, 0, 0);
  const Eigen::Vector2d eye(cam.translation().x(), cam.translation().y());
  const double heading = std::atan2(cam.linear()(1, 0), cam.linear()(0, 0));
  auto ballAt = [&](double off_deg, double from_eye_m) {
    const double a = heading + off_deg * kDeg;
    const Eigen::Vector2d b = eye + from_eye_m * Eigen::Vector2d(std::cos(a), std::sin(a));
    world.placeBall(b.x(), b.y());
    return ofType(o.observe(world, 0, 0), al::ObservationType::Ball);
  };
  EXPECT_EQ(ballAt(29, 2.35).size(), 1u);  // ~2.4 m from the robot, inside 30 deg
  EXPECT_TRUE(ballAt(31, 2.35).empty());
  EXPECT_TRUE(ballAt(-31, 2.35).empty());
  EXPECT_TRUE(ballAt(0, 2.6).empty());  // beyond 2500 mm
  // Right at the feet: far below the cameras' vertical field of view, still reported.
  EXPECT_EQ(ballAt(0, 0.12).size(), 1u);
  // Behind another robot: no occlusion.
  const auto seen = ballAt(0, 2.0);
  ASSERT_EQ(seen.size(), 1u);
  world.addRobot(model(), eye.x() + std::cos(heading) * 1.0, eye.y() + std::sin(heading) * 1.0, M_PI, stand());
  EXPECT_EQ(ofType(o.observe(world, 0, 0), al::ObservationType::Ball).size(), 1u);
  // Exact, robot-relative.
  const Eigen::Vector2d rel = o.groundFrame(world, 0).toRobot(Eigen::Vector2d(world.ballPosition().x(), world.ballPosition().y())) * 1000;
  EXPECT_NEAR(seen[0].obs.distance, rel.norm(), 0.5);
}

TEST(VisionConfig, PresetSimswift2017IsReadFromTheScenario) {
  const runner::Scenario s = runner::Scenario::parse("duration: 1\nvision: {preset: simswift2017}\nrobots:\n  - {team: 19, player: 1}\n",
                                     "p.yaml");
  EXPECT_EQ(s.vision.ball_model, BallModel::Thesis2017);
  EXPECT_EQ(s.vision[Feature::Ball].max_distance_mm, 2500);
  EXPECT_EQ(s.vision[Feature::Ball].false_positive_rate, 0);
  try {
    runner::Scenario::parse("duration: 1\nvision: {preset: simspark}\nrobots:\n  - {team: 19, player: 1}\n", "p.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const simswift::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("p.yaml:2: vision.preset"), std::string::npos) << e.what();
  }
}

TEST_F(OneRobot, BallJustInsideAndJustOutsideTheDistanceLimit) {
  VisionOracle o(world.field(), exact(), 1);
  const GroundFrame g = o.groundFrame(world, 0);
  const Eigen::Vector2d fwd(std::cos(g.heading), std::sin(g.heading));
  for (double d_mm : {2490.0, 2510.0}) {
    const Eigen::Vector2d b = g.origin + fwd * d_mm * 1e-3;
    world.placeBall(b.x(), b.y());
    const auto seen = ofType(o.observe(world, 0, 0), al::ObservationType::Ball);
    EXPECT_EQ(seen.size(), d_mm < 2500 ? 1u : 0u) << d_mm << " mm";
  }
  // A shorter configured range moves the limit.
  VisionConfig c = exact();
  c[Feature::Ball].max_distance_mm = 1500;
  c[Feature::Ball].falloff_start_mm = 1500;
  VisionOracle o2(world.field(), c, 1);
  for (double d_mm : {1490.0, 1510.0}) {
    const Eigen::Vector2d b = g.origin + fwd * d_mm * 1e-3;
    world.placeBall(b.x(), b.y());
    // (at 1.5 m the ball is in both cameras' images)
    EXPECT_EQ(ofType(o2.observe(world, 0, 0), al::ObservationType::Ball).empty(), d_mm > 1500) << d_mm;
  }
}

TEST(VisionOracleScene, BallHiddenBehindARobotIsNotSeen) {
  World world(FieldConfig::spl2017());
  world.addRobot(model(), -1.0, 0.0, 0.0, stand());
  const int blocker = world.addRobot(model(), 0.0, 0.0, M_PI, stand());
  world.placeBall(0.8, 0.0);
  VisionOracle o(world.field(), exact(), 1);
  EXPECT_TRUE(ofType(o.observe(world, 0, 0), al::ObservationType::Ball).empty());
  // The blocker itself is seen, with its team and facing.
  o.setTeams({18, 5}, {0, 1});
  const auto robots = ofType(o.observe(world, 0, 0), al::ObservationType::Robot, 0);
  ASSERT_EQ(robots.size(), 1u);
  EXPECT_EQ(robots[0].obs.team, 5);
  EXPECT_EQ(robots[0].obs.colour, 1);
  EXPECT_NEAR(std::abs(robots[0].obs.orientation), M_PI, 0.05);
  EXPECT_NEAR(robots[0].obs.x, 1000, 30);
  EXPECT_EQ(robots[0].obs.flags & al::kObservationRobotFallen, 0);
  // Step aside: the ball is seen.
  world.placeRobot(blocker, 0.0, 1.2, M_PI, stand());
  EXPECT_EQ(ofType(o.observe(world, 0, 0), al::ObservationType::Ball).size(), 1u);
  for (const SeenObject& s : o.observe(world, 0, 0)) {
    if (s.obs.type != al::ObservationType::Robot) {
      EXPECT_EQ(s.obs.colour, -1);
    }
  }
  // Lying on its back 1 m ahead: still seen, flagged fallen.
  Eigen::Isometry3d lying = Eigen::Isometry3d::Identity();
  lying.linear() = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  lying.translation() = Eigen::Vector3d(0.0, 0.3, 0.1);
  world.robot(blocker).teleport(lying);
  const auto down = ofType(o.observe(world, 0, 0), al::ObservationType::Robot);
  ASSERT_GE(down.size(), 1u);
  EXPECT_NE(down[0].obs.flags & al::kObservationRobotFallen, 0);
}

TEST(VisionOracleScene, BallHiddenBehindAGoalPostIsNotSeen) {
  World world(FieldConfig::spl2017());
  const double post_y = 0.75 + 0.05;  // SPL: inner width 1.5 m, posts 0.1 m
  world.addRobot(model(), 2.5, post_y, 0.0, stand());
  VisionOracle o(world.field(), exact(), 1);
  world.placeBall(4.8, post_y);  // in the goal, right behind the left post
  EXPECT_TRUE(ofType(o.observe(world, 0, 0), al::ObservationType::Ball).empty());
  world.placeBall(4.8, post_y - 0.3);
  EXPECT_EQ(ofType(o.observe(world, 0, 0), al::ObservationType::Ball).size(), 1u);
}

TEST(VisionOracleScene, SeesFieldFeaturesWithKinds) {
  World world(FieldConfig::spl2017());
  world.addRobot(model(), 1.6, 0.0, 0.0, stand());  // facing the opponent penalty area
  VisionOracle o(world.field(), exact(), 1);
  const auto seen = o.observe(world, 0, 0);
  const auto posts = ofType(seen, al::ObservationType::GoalPost, 0);
  EXPECT_EQ(posts.size(), 2u);
  const auto marks = ofType(seen, al::ObservationType::PenaltyCross);
  ASSERT_GE(marks.size(), 1u);
  EXPECT_NEAR(marks[0].obs.x, (3.2 - 1.6) * 1000, 60);  // robot origin is between the feet, not the torso
  EXPECT_NEAR(marks[0].obs.y, 0, 10);
  int t = 0, l = 0;
  for (const SeenObject& s : ofType(seen, al::ObservationType::LineCorner)) {
    t += s.obs.corner == al::CornerKind::T;
    l += s.obs.corner == al::CornerKind::L;
  }
  EXPECT_GE(l, 2);  // penalty-area corners at (3.9, +-1.1), 2.3 m ahead
  const auto lines = ofType(seen, al::ObservationType::FieldLine);
  ASSERT_GE(lines.size(), 1u);
  for (const SeenObject& s : lines) {
    const double len = std::hypot(s.obs.x2 - s.obs.x, s.obs.y2 - s.obs.y);
    EXPECT_GE(len, 200 - 1e-3);
    EXPECT_LE(s.obs.distance, 3500 + 1);
  }
  // Everything fits one frame, highest priority first.
  al::CameraFrame f{};
  f.frame_index = 0;
  EXPECT_EQ(o.fill(world, 0, f), 0);
  EXPECT_EQ(f.num_observations, static_cast<int>(seen.size()));
  EXPECT_EQ(f.observations[0].type, al::ObservationType::GoalPost);
}

TEST_F(OneRobot, NoiseStatisticsMatchTheConfiguredSigmas) {
  VisionConfig c;
  c.camera_offset_mm = 0;
  DetectorSpec& b = c[Feature::Ball];
  b.p_near = b.p_at_max = 1.0;
  b.distance_sigma_mm = 40;
  b.distance_sigma_fraction = 0;
  b.elevation_sigma_deg = 0;
  b.bearing_sigma_deg = 2.0;
  VisionOracle o(world.field(), c, 7);
  const GroundFrame g = o.groundFrame(world, 0);
  const Eigen::Vector2d ball = g.origin + Eigen::Vector2d(1.2, 0.2);
  world.placeBall(ball.x(), ball.y());
  const Eigen::Vector2d rel = g.toRobot(ball) * 1000;
  const double d0 = rel.norm(), h0 = std::atan2(rel.y(), rel.x());
  const int n = 4000;
  double sd = 0, sdd = 0, sh = 0, shh = 0;
  int k = 0;
  for (int frame = 0; frame < n; ++frame)
    for (const SeenObject& s : ofType(o.observe(world, 0, frame), al::ObservationType::Ball, 0)) {
      const double dd = s.obs.distance - d0, dh = s.obs.heading - h0;
      sd += dd, sdd += dd * dd, sh += dh, shh += dh * dh;
      ++k;
    }
  ASSERT_EQ(k, n);  // p = 1: seen every frame
  const double mean_d = sd / k, std_d = std::sqrt(sdd / k - mean_d * mean_d);
  const double mean_h = sh / k, std_h = std::sqrt(shh / k - mean_h * mean_h);
  // Sample sigma of n Gaussian draws: relative spread 1/sqrt(2n) = 1.1 %; allow 5 %.
  EXPECT_NEAR(std_d, 40.0, 2.0);
  EXPECT_NEAR(std_h, 2.0 * kDeg, 0.1 * kDeg);
  EXPECT_NEAR(mean_d, 0.0, 4 * 40.0 / std::sqrt(n));  // unbiased
  EXPECT_NEAR(mean_h, 0.0, 4 * 2.0 * kDeg / std::sqrt(n));

  // The vertical-angle error reaches the distance through the camera height:
  // sigma_d = (h^2 + dc^2) / h * sigma_elev.
  b.distance_sigma_mm = 0;
  b.bearing_sigma_deg = 0;
  b.elevation_sigma_deg = 0.5;
  VisionOracle oe(world.field(), c, 8);
  const Eigen::Vector3d eye = oe.cameraPose(world, 0, 0).translation();
  const double h = eye.z() - world.ballPosition().z();
  const double dc = (Eigen::Vector2d(eye.x(), eye.y()) - ball).norm();
  const double expect = (h * h + dc * dc) / h * 0.5 * kDeg * 1000;  // mm
  double s2 = 0, s1 = 0;
  for (int frame = 0; frame < n; ++frame) {
    const auto v = ofType(oe.observe(world, 0, frame), al::ObservationType::Ball, 0);
    ASSERT_EQ(v.size(), 1u);
    s1 += v[0].obs.distance - d0;
    s2 += (v[0].obs.distance - d0) * (v[0].obs.distance - d0);
  }
  EXPECT_NEAR(std::sqrt(s2 / n - (s1 / n) * (s1 / n)), expect, 0.05 * expect);
}

TEST_F(OneRobot, FalsePositiveRateMatchesTheConfiguredRate) {
  VisionConfig c;
  c[Feature::Ball].false_positive_rate = 0.1;
  VisionOracle o(world.field(), c, 11);
  world.placeBall(-4.0, 0.0);  // behind the robot: never really seen
  const int n = 4000;
  int fp[2] = {0, 0};
  for (int frame = 0; frame < n; ++frame)
    for (const SeenObject& s : ofType(o.observe(world, 0, frame), al::ObservationType::Ball)) {
      ASSERT_TRUE(s.false_positive);
      EXPECT_LE(s.obs.distance, 2500 + 1);
      ++fp[s.obs.camera];
    }
  // Binomial(4000, 0.1): sigma 0.0047; allow 0.02.
  EXPECT_NEAR(fp[0] / double(n), 0.1, 0.02);
  EXPECT_NEAR(fp[1] / double(n), 0.1, 0.02);
  // Rate 0 (the default): none.
  VisionOracle none(world.field(), VisionConfig{}, 11);
  int any = 0;
  for (int frame = 0; frame < 500; ++frame) any += ofType(none.observe(world, 0, frame), al::ObservationType::Ball).size();
  EXPECT_EQ(any, 0);
}

TEST_F(OneRobot, DetectionRateFallsWithDistanceAsConfigured) {
  VisionConfig c;  // ball: p 1 up to 1500 mm, then linearly to 0.7 at 2500 mm
  VisionOracle o(world.field(), c, 3);
  const GroundFrame g = o.groundFrame(world, 0);
  auto rate = [&](double d_mm) {
    const Eigen::Vector2d b = g.origin + Eigen::Vector2d(d_mm * 1e-3, 0.1);  // off every line
    world.placeBall(b.x(), b.y());
    const int n = 3000;
    int seen = 0;
    for (int frame = 0; frame < n; ++frame) seen += ofType(o.observe(world, 0, frame), al::ObservationType::Ball, 0).size();
    return seen / double(n);
  };
  const double expect_2000 = c[Feature::Ball].probability(std::hypot(2000.0, 100.0));
  EXPECT_NEAR(expect_2000, 0.85, 0.01);
  EXPECT_NEAR(rate(1400), 1.0, 1e-9);
  EXPECT_NEAR(rate(2000), expect_2000, 0.03);  // binomial sigma 0.0065
  EXPECT_NEAR(rate(2450), c[Feature::Ball].probability(std::hypot(2450.0, 100.0)), 0.03);
}

TEST(VisionOracleScene, BallOnALineIsDetectedLessOften) {
  World world(FieldConfig::spl2017());
  world.addRobot(model(), -2.0, 0.0, 0.0, stand());  // ~2 m: top camera only
  VisionConfig c;
  DetectorSpec& b = c[Feature::Ball];
  b.p_near = 0.9;
  b.falloff_start_mm = b.max_distance_mm;  // flat 0.9 in range
  b.on_line_factor = 0.5;
  VisionOracle o(world.field(), c, 5);
  auto rate = [&](double x, double y) {
    world.placeBall(x, y);
    const int n = 3000;
    int seen = 0;
    for (int frame = 0; frame < n; ++frame) seen += ofType(o.observe(world, 0, frame), al::ObservationType::Ball, 0).size();
    return seen / double(n);
  };
  // Binomial sigma <= 0.0091 at n = 3000; allow 0.035.
  EXPECT_NEAR(rate(0.0, 0.3), 0.45, 0.035);   // on the halfway line
  EXPECT_NEAR(rate(-0.3, 0.3), 0.9, 0.035);   // 0.3 m off it (and off the circle)
}

TEST(VisionOracleScene, SameSeedSameObservationsOtherSeedOthers) {
  auto run = [](uint64_t seed) {
    World world(FieldConfig::spl2017());
    world.addRobot(model(), -1.0, 0.0, 0.0, stand());
    world.addRobot(model(), 0.5, 0.8, M_PI, stand());
    world.addRobot(model(), 1.5, -0.6, 2.5, stand());
    world.placeBall(0.3, -0.2);
    VisionConfig c;
    c[Feature::Ball].false_positive_rate = 0.2;
    c[Feature::Robot].false_positive_rate = 0.2;
    VisionOracle o(world.field(), c, seed);
    o.setTeams({18, 5, 5}, {0, 1, 1});
    std::vector<al::Observation> all;
    for (int frame = 0; frame < 60; ++frame)
      for (int r = 0; r < 3; ++r)
        for (const SeenObject& s : o.observe(world, r, frame)) all.push_back(s.obs);
    return all;
  };
  const auto a = run(42), b = run(42), c = run(43);
  ASSERT_GT(a.size(), 100u);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(al::Observation)), 0);
  const bool differs = a.size() != c.size() || std::memcmp(a.data(), c.data(), a.size() * sizeof(al::Observation)) != 0;
  EXPECT_TRUE(differs);
}

TEST_F(OneRobot, NothingSeenWhileLying) {
  VisionOracle o(world.field(), exact(), 1);
  world.placeBall(0.0, 0.0);
  EXPECT_FALSE(o.blind(world, 0));
  EXPECT_FALSE(o.observe(world, 0, 0).empty());
  // On its back: torso pitched 90 degrees, 0.1 m above the carpet.
  Eigen::Isometry3d lying = Eigen::Isometry3d::Identity();
  lying.linear() = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  lying.translation() = Eigen::Vector3d(-1.0, 0.0, 0.1);
  world.robot(0).teleport(lying);
  EXPECT_TRUE(o.blind(world, 0));
  EXPECT_TRUE(o.observe(world, 0, 0).empty());
  al::CameraFrame f{};
  o.fill(world, 0, f);
  EXPECT_EQ(f.num_observations, 0);
  // Tilted 30 degrees but still: not lying, not falling.
  Eigen::Isometry3d leaning = Eigen::Isometry3d::Identity();
  leaning.linear() = Eigen::AngleAxisd(30 * kDeg, Eigen::Vector3d::UnitY()).toRotationMatrix();
  leaning.translation() = Eigen::Vector3d(-1.0, 0.0, 0.3);
  world.robot(0).teleport(leaning);
  EXPECT_FALSE(o.blind(world, 0));
  // ... but turning fast at that tilt means falling.
  dBodySetAngularVel(world.robot(0).torsoBody(), 0, 3.0, 0);  // 172 deg/s
  EXPECT_TRUE(o.blind(world, 0));
}

// The runner fills every robot's frame: a Perception thread sees the ball.
// The counts outlive the probe: Runner::run() ends the robot programs, and
// with them their Perception steps.
struct ProbeCounts {
  std::atomic<int> frames{0}, with_ball{0}, bad{0};
};
struct BallProbe : agent::framework::PerceptionStep {
  explicit BallProbe(std::shared_ptr<ProbeCounts> c) : counts(std::move(c)) {}
  std::shared_ptr<ProbeCounts> counts;
  void step(const al::CameraFrame& f) override {
    ++frames_;
    ++counts->frames;
    if (f.num_observations < 0 || f.num_observations > al::kMaxObservations) ++counts->bad;
    for (int i = 0; i < f.num_observations; ++i)
      if (f.observations[i].type == al::ObservationType::Ball && std::abs(f.observations[i].x - 800) < 100 &&
          std::abs(f.observations[i].y - 200) < 100) {  // ball 0.8 m ahead, 0.2 m left of the feet
        ++counts->with_ball;
        break;
      }
  }
};

TEST(VisionRunner, PerceptionThreadReceivesObservations) {
  runner::Scenario sc = runner::Scenario::parse(
      "duration: 1.0\nseed: 3\nball: {x: -0.2, y: 0.2}\n"
      "vision: {ball: {p_near: 1, p_at_max: 1}}\n"
      "robots:\n  - {team: 0, player: 1, x: -1.0, y: 0.0}\n  - {team: 1, player: 2, x: 1.5, y: 1.0, theta: 3.14}\n",
      "vision_runner.yaml");
  runner::Runner r(sc);
  auto p = std::make_shared<ProbeCounts>();
  r.programs().setPerceptionStep(0, std::make_unique<BallProbe>(p));
  runner::RunOptions opt;
  opt.progress = false;
  r.run(opt);
  EXPECT_GE(p->frames.load(), 29);
  EXPECT_EQ(p->bad.load(), 0);
  // Standing still 1 m from the ball, p = 1: every frame once the robot has settled.
  EXPECT_GE(p->with_ball.load(), p->frames.load() - 2);
}

}  // namespace

namespace {

// Every observation a Perception thread received, in order (kept in a
// shared vector: the recorder itself ends with the robot program).
struct Recorder : agent::framework::PerceptionStep {
  explicit Recorder(std::shared_ptr<std::vector<al::Observation>> s) : seen(std::move(s)) {}
  std::shared_ptr<std::vector<al::Observation>> seen;
  void step(const al::CameraFrame& f) override {
    ++frames_;
    seen->insert(seen->end(), f.observations, f.observations + f.num_observations);
  }
};

struct RunRecord {
  std::vector<al::Observation> seen;
  uint64_t hash;
};

RunRecord runRecorded(uint64_t seed, bool vision_on) {
  runner::Scenario sc = runner::Scenario::parse(
      "duration: 0.6\nseed: " + std::to_string(seed) + "\nball: {x: -0.2, y: 0.2}\n" +
          (vision_on ? std::string() : std::string("vision: {enabled: off}\n")) +
          "robots:\n  - {team: 0, player: 1, x: -1.0, y: 0.0}\n  - {team: 1, player: 2, x: 1.0, y: 0.5, theta: 3.14}\n",
      "vision_det.yaml");
  runner::Runner r(sc);
  auto seen = std::make_shared<std::vector<al::Observation>>();
  r.programs().setPerceptionStep(0, std::make_unique<Recorder>(seen));
  runner::RunOptions opt;
  opt.progress = false;
  const runner::RunStats s = r.run(opt);
  return {*seen, s.hash};
}

TEST(VisionRunner, SameSeedSameObservationsAndTheOracleLeavesTheStateHashAlone) {
  const RunRecord a = runRecorded(9, true), b = runRecorded(9, true), off = runRecorded(9, false);
  ASSERT_GT(a.seen.size(), 50u);
  ASSERT_EQ(a.seen.size(), b.seen.size());
  EXPECT_EQ(std::memcmp(a.seen.data(), b.seen.data(), a.seen.size() * sizeof(al::Observation)), 0);
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_TRUE(off.seen.empty());
  EXPECT_EQ(a.hash, off.hash);  // observing changes nothing in the world
}

}  // namespace
