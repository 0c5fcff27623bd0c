// Cameras on a robot in a World: ball pixel in both cameras, identical frames
// for identical worlds, frame dumps, and the overview sequence / video.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "CameraTestUtil.hpp"
#include "agent/program/Postures.hpp"
#include "sim/camera/FrameDumper.hpp"
#include "sim/camera/Overview.hpp"
#include "sim/camera/Png.hpp"
#include "sim/camera/RobotCameras.hpp"
#include "sim/camera/Yuv.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/world/World.hpp"
#include "tests/support/NaoV5Model.hpp"

using namespace simswift;
using namespace simswift::camera;
using namespace camtest;
using common::libagent::CameraImages;

namespace {

using simswift::testing::naoV5Model;

// The robot program's standing posture (agent/program/Postures.hpp), model joint order.
std::vector<double> standingPosture(const RobotModel& m) {
  return simswift::NaoBinding(m).posture(agent::program::postureAngles(agent::program::Posture::Stand));
}

std::vector<uint8_t> copyRgb(const CameraImages& im, int cam) {
  return std::vector<uint8_t>(im.rgb[cam], im.rgb[cam] + im.rgbBytes(cam));
}

}  // namespace

TEST(RobotCameras, BallRelativeToTheRobotAppearsAtTheExpectedPixel) {
  noDisplay();
  World world(FieldConfig{});  // no painted lines: only the ball is grey in its window
  const double theta = 0.3;
  const int robot = world.addRobot(naoV5Model(), -1.0, 0.5, theta, standingPosture(*naoV5Model()));
  RobotCamerasConfig cfg;
  cfg.scene.sky = {0, 0, 1};
  cfg.scene.draw_net = false;
  RobotCameras cams(world, cfg);
  auto images = std::make_unique<CameraImages>();
  const double r = world.field().ball.diameter / 2;
  // Robot-relative ball positions (m, x forward, y left of the robot).
  struct Case { CameraId cam; double x, y; };
  for (const Case& c : {Case{kTop, 1.5, 0.2}, Case{kTop, 2.5, -0.4}, Case{kBottom, 0.45, 0.05},
                        Case{kBottom, 0.35, -0.12}}) {
    SCOPED_TRACE(::testing::Message() << (c.cam == kTop ? "top" : "bottom") << " camera, ball at (" << c.x << ", "
                                    << c.y << ") robot-relative");
    world.placeBall(-1.0 + c.x * std::cos(theta) - c.y * std::sin(theta),
                    0.5 + c.x * std::sin(theta) + c.y * std::cos(theta));
    cams.fillImages(world, robot, *images);
    ASSERT_EQ(images->valid[c.cam], 1);
    const CameraModel model = cams.camera(world, robot, c.cam);
    const Blob expected = sphereImage(model, world.ballPosition(), r);
    ASSERT_GT(expected.area, 30) << "ball not in the camera's view";
    const Blob seen = ballNear(copyRgb(*images, c.cam), images->size[c.cam].width, images->size[c.cam].height,
                                expected);
    EXPECT_NEAR(seen.u, expected.u, 2.0);
    EXPECT_NEAR(seen.v, expected.v, 2.0);
    EXPECT_NEAR(double(seen.area) / expected.area, 1.0, 0.1);
  }
}

// A V6 renders through its own lens (56.3 x 43.7 deg against the V5's 60.9 x
// 47.6): the same ball, seen from the same head, lies 1.099 times as far
// from the image centre (the ratio of the focal lengths) and looks larger.
TEST(RobotCameras, AV6RendersThroughItsNarrowerLens) {
  noDisplay();
  World world(FieldConfig{});
  const int robot = world.addRobot(naoV5Model(), -1.0, 0.0, 0.0, standingPosture(*naoV5Model()));
  world.placeBall(-1.0 + 1.6, 0.3);  // 1.6 m ahead, 0.3 m to the left
  Blob seen[2];
  for (int k = 0; k < 2; ++k) {
    RobotCamerasConfig cfg;
    cfg.scene.sky = {0, 0, 1};
    cfg.scene.draw_net = false;
    cfg.lens = k == 0 ? common::nao::kV5CameraLens : common::nao::kV6CameraLens;
    RobotCameras cams(world, cfg);
    auto images = std::make_unique<CameraImages>();
    cams.fillImages(world, robot, *images);
    const CameraModel model = cams.camera(world, robot, kTop);
    const Blob expected = sphereImage(model, world.ballPosition(), world.field().ball.diameter / 2);
    ASSERT_GT(expected.area, 30) << "ball not in the top camera's view";
    seen[k] = ballNear(copyRgb(*images, kTop), images->size[kTop].width, images->size[kTop].height, expected);
    EXPECT_NEAR(seen[k].u, expected.u, 2.0) << (k ? "V6" : "V5");
    EXPECT_NEAR(seen[k].v, expected.v, 2.0) << (k ? "V6" : "V5");
  }
  const double ratio = (seen[1].u - 320.0) / (seen[0].u - 320.0);
  EXPECT_NEAR(ratio, 598.05 / 544.34, 0.03);
  EXPECT_GT(seen[1].area, seen[0].area);
}

// Each camera at its own resolution (the V6 pair of rUNSWift 2019-2022: top
// 1280x960, bottom 640x480, and the reverse): the block says each size, and
// the same ball lies at the same normalised image position at both scales,
// within 1 px at 640x480.
TEST(RobotCameras, EachCameraAtItsOwnResolutionSeesTheBallAtTheSamePlace) {
  noDisplay();
  World world(FieldConfig{});
  const int robot = world.addRobot(naoV5Model(), -1.0, 0.0, 0.0, standingPosture(*naoV5Model()));
  const common::libagent::ImageSize small{640, 480}, large{1280, 960};
  // Robot-relative ball positions (m) in view of each camera.
  struct Case { CameraId cam; double x, y; };
  for (const Case& c : {Case{kTop, 1.6, 0.3}, Case{kTop, 2.4, -0.5}, Case{kBottom, 0.4, 0.08}}) {
    SCOPED_TRACE(::testing::Message() << (c.cam == kTop ? "top" : "bottom") << " camera, ball at (" << c.x << ", "
                                    << c.y << ")");
    world.placeBall(-1.0 + c.x, c.y);
    Blob seen[2];  // at 640x480, at 1280x960
    for (int k = 0; k < 2; ++k) {
      RobotCamerasConfig cfg;
      cfg.scene.sky = {0, 0, 1};
      cfg.scene.draw_net = false;
      cfg.resolution[c.cam] = k == 0 ? small : large;
      cfg.resolution[1 - c.cam] = k == 0 ? large : small;  // the other camera: the other size
      RobotCameras cams(world, cfg);
      auto images = std::make_unique<CameraImages>();
      cams.fillImages(world, robot, *images);
      ASSERT_EQ(images->size[c.cam], cfg.resolution[c.cam]);
      ASSERT_EQ(images->size[1 - c.cam], cfg.resolution[1 - c.cam]);
      const common::libagent::ImageSize size = images->size[c.cam];
      const Blob expected = sphereImage(cams.camera(world, robot, c.cam), world.ballPosition(),
                                        world.field().ball.diameter / 2);
      ASSERT_GT(expected.area, 30) << "ball not in the camera's view";
      seen[k] = ballNear(copyRgb(*images, c.cam), size.width, size.height, expected);
    }
    // 1280x960 halved onto 640x480.
    EXPECT_NEAR(seen[1].u / 2, seen[0].u, 1.0);
    EXPECT_NEAR(seen[1].v / 2, seen[0].v, 1.0);
    EXPECT_NEAR(double(seen[1].area) / (4 * seen[0].area), 1.0, 0.1);
  }
  RobotCameras cams(world);
  EXPECT_THROW(cams.setResolution(kTop, {1281, 960}), std::invalid_argument);
  EXPECT_THROW(cams.setResolution(kBottom, {2560, 1920}), std::invalid_argument);
}

TEST(RobotCameras, IdenticalWorldsRenderIdenticalFramesAndYuvMatchesRgb) {
  noDisplay();
  uint64_t hashes[2][2];
  for (int run = 0; run < 2; ++run) {
    World world(FieldConfig::spl2017());
    world.addRobot(naoV5Model(), 0, 0, 0, standingPosture(*naoV5Model()));
    world.addRobot(naoV5Model(), 0.8, 0.1, M_PI, standingPosture(*naoV5Model()));
    world.placeBall(0.4, 0.05);
    for (int i = 0; i < 20; ++i) world.step();
    RobotCameras cams(world);
    cams.setTeams({0, 1});
    auto images = std::make_unique<CameraImages>();
    cams.fillImages(world, 0, *images);
    for (int c = 0; c < 2; ++c) hashes[run][c] = fnv1a(images->yuv422[c], images->yuvBytes(c));
    if (run == 0) {
      // The YUV buffer is the RGB buffer converted.
      std::vector<uint8_t> yuv(images->yuvBytes(0));
      rgbToYuyv(images->rgb[0], images->size[0].width, images->size[0].height, yuv.data());
      EXPECT_EQ(fnv1a(yuv), hashes[0][0]);
      EXPECT_EQ(images->magic, common::libagent::kCameraImagesMagic);
      EXPECT_EQ(images->frame_index, 6);  // 0.2 s at 30 Hz
      EXPECT_EQ(images->sim_time_us, 200000);
      // The other robot (team 1, red) stands in the top camera's view.
      const auto top = copyRgb(*images, 0);
      const Blob red = blob(top, 640, 480, [](const uint8_t* p) { return p[0] > 110 && p[0] > 3 * p[1] && p[0] > 3 * p[2]; });
      EXPECT_GT(red.area, 200);
      if (std::getenv("SIMSWIFT_KEEP_TEST_IMAGES")) {
        writePng(freshDir("two-robots") + "/top.png", images->rgb[0], 640, 480);
        writePng(freshDir("two-robots-b") + "/bottom.png", images->rgb[1], 640, 480);
      }
    }
  }
  EXPECT_EQ(hashes[0][0], hashes[1][0]);
  EXPECT_EQ(hashes[0][1], hashes[1][1]);
  EXPECT_NE(hashes[0][0], hashes[0][1]);
}

TEST(FrameDumper, WritesEveryNthFrameForBothCameras) {
  noDisplay();
  const std::string dir = freshDir("dump");
  World world(FieldConfig::spl2017());
  world.addRobot(naoV5Model(), 0, 0, 0, standingPosture(*naoV5Model()));
  RobotCameras cams(world);
  FrameDumper dumper(dir, 3);
  auto images = std::make_unique<CameraImages>();
  for (int64_t frame = 0; frame <= 6; ++frame) {
    cams.fillImages(world, 0, *images, frame);
    dumper.dump(1, 3, *images);
  }
  EXPECT_EQ(dumper.written(), 6);  // frames 0, 3, 6 x top and bottom
  for (int frame : {0, 3, 6})
    for (const char* cam : {"top", "bottom"}) {
      char name[64];
      std::snprintf(name, sizeof name, "/t1p3_%s_%06d.png", cam, frame);
      int w = 0, h = 0;
      const auto png = readPng(dir + name, &w, &h);
      EXPECT_EQ(w, 640);
      EXPECT_EQ(h, 480);
    }
  EXPECT_FALSE(std::filesystem::exists(dir + "/t1p3_top_000001.png"));
  // The PNG holds exactly the RGB buffer.
  int w = 0, h = 0;
  EXPECT_EQ(readPng(dir + "/t1p3_bottom_000006.png", &w, &h), copyRgb(*images, 1));
  EXPECT_THROW(FrameDumper(dir, 0), std::invalid_argument);
}

TEST(Overview, ShortRunGivesTheExpectedFramesAndVideo) {
  noDisplay();
  const std::string dir = freshDir("overview");
  World world(FieldConfig::spl2017());
  world.addRobot(naoV5Model(), -1.0, 0.0, 0, standingPosture(*naoV5Model()));
  world.placeBall(0, 0);
  world.setBallVelocity({1.0, 0.3, 0});
  RobotCameras cams(world);
  OverviewConfig cfg;
  cfg.dir = dir;
  cfg.rate_hz = 10;
  cfg.width = 320;
  cfg.height = 180;
  cfg.mode = OverviewConfig::Mode::FollowBall;
  OverviewCamera overview(cfg);
  EXPECT_TRUE(overview.maybeCapture(cams, world));  // t = 0
  for (int tick = 0; tick < 50; ++tick) {             // 0.5 s
    world.step();
    overview.maybeCapture(cams, world);
  }
  EXPECT_EQ(overview.frames(), 6);  // t = 0, 0.1, ..., 0.5 s
  int pngs = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) pngs += e.path().extension() == ".png";
  EXPECT_EQ(pngs, 6);
  EXPECT_TRUE(std::filesystem::exists(dir + "/overview_000005.png"));
  const VideoResult video = overview.finish(dir + "/overview.mp4");
  if (VideoWriter::ffmpegOnPath()) {
    EXPECT_TRUE(video.ok) << video.message;
    EXPECT_GT(std::filesystem::file_size(dir + "/overview.mp4"), 1000u);
  } else {
    EXPECT_FALSE(video.ok);
    EXPECT_NE(video.message.find("PNG"), std::string::npos);
  }
}
