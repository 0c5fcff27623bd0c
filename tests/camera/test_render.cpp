// Rendering against the camera model with free camera poses (no World):
// ball position, goal post edges, determinism, meshes through assimp.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "CameraTestUtil.hpp"
#include "sim/camera/Renderer.hpp"
#include "sim/camera/Scene.hpp"

using namespace simswift;
using namespace simswift::camera;
using namespace camtest;

namespace {

// Plain field (no painted lines, no net), pure blue sky: only the objects
// under test are neither green nor blue.
SceneOptions testOptions() {
  SceneOptions o;
  o.sky = {0, 0, 1};
  o.draw_net = false;
  return o;
}

// A head where a standing NAO's would be (m, field), facing +x, level.
Eigen::Isometry3d standingHead() {
  Eigen::Isometry3d head = Eigen::Isometry3d::Identity();
  head.translation() = Eigen::Vector3d(0, 0, 0.46);
  return head;
}

// The ball centre whose projection is pixel (u, v): on that pixel's ray, at
// ball height.
Eigen::Vector3d ballSeenAt(const CameraModel& cam, double u, double v, double radius) {
  const Eigen::Vector3d o = cam.pose.translation(), d = cam.rayDirection(u, v);
  return o + d * ((radius - o.z()) / d.z());
}

}  // namespace

TEST(Render, BallAppearsWhereTheCameraModelPutsIt) {
  noDisplay();
  FieldConfig field;  // no lines
  Scene scene(field, testOptions());
  Renderer renderer;
  const double r = field.ball.diameter / 2;
  struct Case { CameraId cam; double u, v; };
  const Case cases[] = {{kTop, 320, 300}, {kTop, 500, 400}, {kTop, 110, 350},
                        {kBottom, 320, 240}, {kBottom, 140, 90}, {kBottom, 530, 420}};
  for (const Case& c : cases) {
    SCOPED_TRACE(::testing::Message() << (c.cam == kTop ? "top" : "bottom") << " camera, target pixel (" << c.u
                                    << ", " << c.v << ")");
    CameraView view;
    view.camera = CameraModel::naoCamera(standingHead(), c.cam);
    scene.ball_position = ballSeenAt(view.camera, c.u, c.v, r);
    const auto img = renderer.render(scene, view);
    const Blob expected = sphereImage(view.camera, scene.ball_position, r);
    const Blob seen = ballNear(img, 640, 480, expected);
    ASSERT_GT(seen.area, 20);
    EXPECT_NEAR(seen.u, expected.u, 2.0);
    EXPECT_NEAR(seen.v, expected.v, 2.0);
    EXPECT_NEAR(double(seen.area) / expected.area, 1.0, 0.05);
    // The centre's projection is the target pixel; the outline's centroid
    // differs from it only by perspective (a few px at most here).
    const auto centre = view.camera.project(scene.ball_position);
    ASSERT_TRUE(centre);
    EXPECT_NEAR(centre->x(), c.u, 1e-6);
    EXPECT_NEAR(std::hypot(seen.u - c.u, seen.v - c.v), 0.0, 6.0);
  }
}

TEST(Render, GoalPostEdgesFallOnTheProjectedSilhouette) {
  noDisplay();
  FieldConfig field;
  Scene scene(field, testOptions());
  scene.show_ball = false;
  Renderer renderer;
  const Eigen::Vector2d post = Scene::goalPostCentre(field, 1, 1);  // opponent goal, left post
  const double R = field.goal.post_diameter / 2;
  CameraView view;
  const Eigen::Vector3d eye(post.x() - 1.5, post.y() - 0.5, 0.4);
  view.camera.pose = lookAt(eye, {post.x(), post.y(), 0.4});  // level: verticals stay vertical
  const auto img = renderer.render(scene, view);

  // Silhouette: the vertical lines through the tangent points seen from the eye.
  const Eigen::Vector2d e = eye.head<2>(), to = post - e;
  const double d = to.norm(), beta = std::asin(R / d), reach = std::sqrt(d * d - R * R);
  auto tangent = [&](double sign) {
    const Eigen::Vector2d dir = Eigen::Rotation2Dd(sign * beta) * (to / d);
    return Eigen::Vector2d(e + dir * reach);
  };
  const Eigen::Vector2d t_left = tangent(+1), t_right = tangent(-1);  // +beta turns left (toward +y)
  auto isPost = [](const uint8_t* p) { return !isGreen(p) && !isBlue(p); };
  int rows = 0;
  for (double z : {0.15, 0.3, 0.45, 0.6}) {
    const auto pl = view.camera.project({t_left.x(), t_left.y(), z});
    const auto pr = view.camera.project({t_right.x(), t_right.y(), z});
    ASSERT_TRUE(pl && pr);
    const int row = static_cast<int>(std::floor(pl->y()));
    ASSERT_GE(row, 0);
    ASSERT_LT(row, 480);
    // Walk out from the middle of the predicted span to the post's edges.
    int c = static_cast<int>((pl->x() + pr->x()) / 2);
    ASSERT_TRUE(isPost(px(img, 640, c, row))) << "row " << row;
    int left = c, right = c;
    while (left > 0 && isPost(px(img, 640, left - 1, row))) --left;
    while (right < 639 && isPost(px(img, 640, right + 1, row))) ++right;
    // Left edge at the first post column's left side; right edge after the last.
    EXPECT_NEAR(left, pl->x(), 1.0) << "z " << z;
    EXPECT_NEAR(right + 1, pr->x(), 1.0) << "z " << z;
    ++rows;
  }
  EXPECT_EQ(rows, 4);
}

TEST(Render, SameSceneGivesIdenticalBytes) {
  noDisplay();
  FieldConfig field = FieldConfig::spl2017();
  Scene scene(field);
  scene.ball_position = {1.0, 0.3, 0.05};
  scene.ball_orientation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  CameraView view;
  view.camera = CameraModel::naoCamera(standingHead(), kTop);
  Renderer a;
  const uint64_t h1 = fnv1a(a.render(scene, view));
  const uint64_t h2 = fnv1a(a.render(scene, view));
  Renderer b;  // a second context
  const uint64_t h3 = fnv1a(b.render(scene, view));
  EXPECT_EQ(h1, h2);
  EXPECT_EQ(h1, h3);
  // Rotating the ball changes the picture: the hash does discriminate.
  scene.ball_orientation = Eigen::AngleAxisd(1.2, Eigen::Vector3d(1, 2, 3).normalized());
  EXPECT_NE(fnv1a(a.render(scene, view)), h1);
}

TEST(Render, WorksWithoutADisplayAtBothResolutions) {
  unsetenv("DISPLAY");
  ASSERT_EQ(std::getenv("DISPLAY"), nullptr);
  Scene scene(FieldConfig::spl2017());
  Renderer renderer;
  for (int w : {640, 1280}) {
    CameraView view;
    view.camera = CameraModel::naoCamera(standingHead(), kBottom, w, w * 3 / 4);
    const auto img = renderer.render(scene, view);
    ASSERT_EQ(img.size(), size_t(w) * (w * 3 / 4) * 3);
    // The bottom camera looks at the carpet: mostly green.
    const Blob green = blob(img, w, w * 3 / 4, isGreen);
    EXPECT_GT(green.area, int64_t(w) * (w * 3 / 4) * 8 / 10);
  }
}

TEST(Render, MeshThroughAssimpCoversTheSamePixelsAsTheBox) {
  noDisplay();
  // The NAO URDF with its torso's visual box (the first <box> in the file)
  // swapped for the geometry under test.
  std::ifstream in(SIMSWIFT_SOURCE_DIR "/models/nao_v5.urdf");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string nao = ss.str(), torso_box = "<box size=\"0.09 0.12 0.16\"/>";
  ASSERT_NE(nao.find(torso_box), std::string::npos);
  auto urdf = [&](const std::string& geometry) {
    std::string s = nao;
    return s.replace(s.find(torso_box), torso_box.size(), geometry);
  };
  const RobotModel box = RobotModel::loadUrdfString(urdf("<box size='0.1 0.1 0.1'/>"), "box.urdf");
  const RobotModel mesh = RobotModel::loadUrdfString(
      urdf("<mesh filename='package://simswift/models/meshes/cube_100mm.obj'/>"), "mesh.urdf");
  SceneOptions opt = testOptions();
  opt.mesh_dirs = {SIMSWIFT_SOURCE_DIR};
  opt.draw_jerseys = false;
  Scene scene(FieldConfig{}, opt);
  scene.show_ball = false;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.8, 0.1, 0.2);
  pose.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  CameraView view;
  view.camera.pose = lookAt({0, 0, 0.5}, pose.translation());
  Renderer renderer;
  std::vector<std::vector<uint8_t>> masks;
  for (const RobotModel* m : {&box, &mesh}) {
    // Torso at `pose`; every other link far behind the camera, out of view.
    Eigen::Isometry3d away = Eigen::Isometry3d::Identity();
    away.translation() = Eigen::Vector3d(-50, 0, 0);
    std::vector<Eigen::Isometry3d> poses(m->links().size(), away);
    poses[m->rootLink()] = pose;
    scene.robots = {RobotDrawState{m, 0, poses}};
    scene.preloadModel(*m);
    const auto img = renderer.render(scene, view);
    std::vector<uint8_t> mask(640 * 480);
    for (int i = 0; i < 640 * 480; ++i) mask[i] = !isGreen(&img[i * 3]) && !isBlue(&img[i * 3]);
    masks.push_back(mask);
  }
  int64_t on = 0, differ = 0;
  for (int i = 0; i < 640 * 480; ++i) on += masks[0][i], differ += masks[0][i] != masks[1][i];
  EXPECT_GT(on, 5000);             // the cube is in view (~0.13 m across at ~0.9 m)
  EXPECT_LE(differ, on / 200);     // same silhouette up to edge pixels
  // The shipped head shell loads through assimp too.
  const RobotModel head = RobotModel::loadUrdfString(
      urdf("<mesh filename='package://simswift/models/meshes/head_shell.obj'/>"), "head.urdf");
  EXPECT_NO_THROW(scene.preloadModel(head));
  // A missing mesh is a clear error naming the link and file.
  const RobotModel bad = RobotModel::loadUrdfString(urdf("<mesh filename='meshes/nope.obj'/>"), "bad.urdf");
  try {
    scene.preloadModel(bad);
    FAIL() << "no error for a missing mesh";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("torso"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("nope.obj"), std::string::npos) << e.what();
  }
}
