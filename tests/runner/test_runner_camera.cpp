// The runner's camera hook: frame dumps, images reaching the Perception
// thread, the overview sequence and the scenario's camera keys.
#ifdef SIMSWIFT_HAVE_CAMERAS

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>

#include "sim/camera/Png.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"
#include "sim/world/ConfigError.hpp"
#include "tests/runner/RunnerTestUtil.hpp"

namespace {

namespace fs = std::filesystem;
namespace al = common::libagent;
using simswift::runner::Runner;
using simswift::runner::RunOptions;
using simswift::runner::Scenario;

std::string tempDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("simswift_camtest_" + std::to_string(getpid()) + "_" + name);
  fs::remove_all(d);
  return d.string();
}

int countFiles(const std::string& dir, const std::string& prefix, const std::string& suffix) {
  int n = 0;
  if (!fs::exists(dir)) return 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string f = e.path().filename().string();
    if (f.rfind(prefix, 0) == 0 && f.size() >= suffix.size() && f.compare(f.size() - suffix.size(), suffix.size(), suffix) == 0)
      ++n;
  }
  return n;
}

// Records what the Perception thread saw of the images, frame by frame.
// Only frames whose cameras have the expected sizes count as non-empty.
struct ImageProbe : agent::framework::PerceptionStep {
  explicit ImageProbe(al::ImageSize top = {}, al::ImageSize bottom = {}) : expected{top, bottom} {}
  const al::ImageSize expected[al::kNumCameras];
  std::atomic<int> valid_frames{0}, nonempty_frames{0}, frames_seen{0};
  std::atomic<int64_t> last_index{-1};
  void step(const al::CameraFrame& frame) override {
    ++frames_;
    ++frames_seen;
    const al::CameraImages* im = images();
    if (!frame.images_valid || !im) return;
    ++valid_frames;
    if (im->magic != al::kCameraImagesMagic || im->frame_index != frame.frame_index || im->size[0] != expected[0] ||
        im->size[1] != expected[1] || !im->valid[0] || !im->valid[1])
      return;
    // Non-empty: the top camera's picture is not one flat colour, and the
    // bottom camera's YUYV luma varies too (field green vs white lines / sky).
    bool rgb_varies = false, y_varies = false;
    for (int64_t i = 3; i < im->rgbBytes(0) && !rgb_varies; i += 3) rgb_varies = im->rgb[0][i] != im->rgb[0][0];
    for (int64_t i = 2; i < im->yuvBytes(1) && !y_varies; i += 2) y_varies = im->yuv422[1][i] != im->yuv422[1][0];
    if (rgb_varies && y_varies) ++nonempty_frames;
    last_index = frame.frame_index;
  }
};

using runnertest::quiet;

Scenario twoRobots(double duration) {
  Scenario sc = Scenario::parse(
      "duration: 0.5\n"
      "seed: 3\n"
      "ball: {x: 0.0, y: 0.0}\n"
      "robots:\n"
      "  - {team: 0, player: 1, x: -1.0, y: 0.0}\n"
      "  - {team: 1, player: 2, x: 1.0, y: 0.5, theta: 3.14159}\n",
      "camtest.yaml");
  sc.duration = duration;
  return sc;
}

// 0.5 s = 50 ticks; camera frame k is taken at the first tick with
// t_us * 30 / 1e6 >= k, so frames 0..15 (16 frames) occur.
constexpr int kFramesIn05s = 16;

TEST(RunnerCamera, DumpFramesWritesEveryNthFramePerRobotAndCamera) {
  Scenario sc = twoRobots(0.5);
  sc.camera.dump_dir = tempDir("dump");
  sc.camera.dump_every = 5;
  Runner runner(sc);
  runner.run(quiet());
  // Frames 0, 5, 10, 15 for each robot and each camera.
  int expected = 0;
  for (int k = 0; k < kFramesIn05s; ++k) expected += k % 5 == 0;
  EXPECT_EQ(expected, 4);
  for (const char* robot : {"t0p1", "t1p2"})
    for (const char* cam : {"_top_", "_bottom_"})
      EXPECT_EQ(countFiles(sc.camera.dump_dir, std::string(robot) + cam, ".png"), expected) << robot << cam;
  EXPECT_EQ(runner.framesDumped(), 2 * 2 * expected);
  EXPECT_TRUE(fs::exists(sc.camera.dump_dir + "/t0p1_top_000015.png"));
  EXPECT_FALSE(fs::exists(sc.camera.dump_dir + "/t0p1_top_000016.png"));
  fs::remove_all(sc.camera.dump_dir);
}

TEST(RunnerCamera, PerceptionThreadSeesImages) {
  Scenario sc = twoRobots(0.3);
  sc.camera.enabled = true;
  Runner runner(sc);
  auto probe = std::make_unique<ImageProbe>();
  ImageProbe* p = probe.get();
  runner.programs().setPerceptionStep(0, std::move(probe));
  runner.run(quiet());
  // 0.3 s: frames 0..9.
  EXPECT_EQ(p->frames_seen.load(), 10);
  EXPECT_EQ(p->valid_frames.load(), 10);
  EXPECT_EQ(p->nonempty_frames.load(), 10);
  EXPECT_EQ(p->last_index.load(), 9);
  ASSERT_NE(runner.images(0), nullptr);
  EXPECT_EQ(runner.images(0)->frame_index, 9);
}

// The NAO V6 pair of rUNSWift 2019-2022 (VisionDefinitions.hpp): top
// 1280x960, bottom 640x480, each in the block and in the dumped frames.
TEST(RunnerCamera, EachCameraAtItsOwnResolution) {
  Scenario sc = Scenario::parse(
      "duration: 0.1\n"
      "seed: 3\n"
      "camera: {enabled: on, resolution: {top: 1280x960, bottom: 640x480}}\n"
      "ball: {x: 0.0, y: 0.0}\n"
      "robots:\n"
      "  - {team: 0, player: 1, x: -1.0, y: 0.0}\n",
      "pair.yaml");
  sc.camera.dump_dir = tempDir("pair");
  Runner runner(sc);
  auto probe = std::make_unique<ImageProbe>(al::ImageSize{1280, 960}, al::ImageSize{640, 480});
  ImageProbe* p = probe.get();
  runner.programs().setPerceptionStep(0, std::move(probe));
  runner.run(quiet());
  EXPECT_EQ(p->frames_seen.load(), 4);  // frames 0..3
  EXPECT_EQ(p->nonempty_frames.load(), 4);
  const al::CameraImages* im = runner.images(0);
  ASSERT_NE(im, nullptr);
  EXPECT_EQ(im->yuvBytes(0), 1280 * 960 * 2);
  EXPECT_EQ(im->rgbBytes(1), 640 * 480 * 3);
  for (const char* cam : {"top", "bottom"}) {
    int w = 0, h = 0;
    simswift::camera::readPng(sc.camera.dump_dir + "/t0p1_" + cam + "_000003.png", &w, &h);
    EXPECT_EQ(w, cam[0] == 't' ? 1280 : 640) << cam;
    EXPECT_EQ(h, cam[0] == 't' ? 960 : 480) << cam;
  }
  fs::remove_all(sc.camera.dump_dir);
}

TEST(RunnerCamera, NoRenderingUnlessAsked) {
  Scenario sc = twoRobots(0.1);
  Runner runner(sc);
  auto probe = std::make_unique<ImageProbe>();
  ImageProbe* p = probe.get();
  runner.programs().setPerceptionStep(0, std::move(probe));
  runner.run(quiet());
  EXPECT_EQ(p->frames_seen.load(), 4);  // frames 0..3 (frame 3 at t = 0.1 s)
  EXPECT_EQ(p->valid_frames.load(), 0);
  EXPECT_EQ(runner.images(0), nullptr);
}

TEST(RunnerCamera, OverviewWritesTenFramesPerSecondPlusFrameZero) {
  Scenario sc = twoRobots(0.5);
  sc.camera.overview.enabled = true;
  sc.camera.overview.mode = simswift::runner::CameraSpec::Overview::Mode::Ball;
  sc.camera.overview.width = 320;
  sc.camera.overview.height = 180;
  sc.camera.overview.dir = tempDir("overview");
  Runner runner(sc);
  runner.run(quiet());
  // Frames at t = 0 (taken after the first step), 0.1, ..., 0.5 s.
  EXPECT_EQ(runner.overviewFrames(), 6);
  EXPECT_EQ(countFiles(sc.camera.overview.dir, "overview_", ".png"), 6);
  EXPECT_FALSE(runner.overviewMessage().empty());
  fs::remove_all(sc.camera.overview.dir);
}

TEST(RunnerCamera, ScenarioCameraKeys) {
  const Scenario sc = Scenario::parse(
      "camera:\n"
      "  enabled: on\n"
      "  resolution: 1280x960\n"
      "  overview: {mode: robot, robot: 1, rate_hz: 5, width: 640, height: 360}\n"
      "robots:\n"
      "  - {team: 0, player: 1}\n"
      "  - {team: 0, player: 2, x: 1}\n",
      "keys.yaml");
  EXPECT_TRUE(sc.camera.enabled);
  for (const al::ImageSize& size : sc.camera.resolution) EXPECT_EQ(size, (al::ImageSize{1280, 960}));
  EXPECT_TRUE(sc.camera.overview.enabled);
  EXPECT_EQ(sc.camera.overview.mode, simswift::runner::CameraSpec::Overview::Mode::Robot);
  EXPECT_EQ(sc.camera.overview.robot, 1);
  EXPECT_DOUBLE_EQ(sc.camera.overview.rate_hz, 5);
  EXPECT_EQ(sc.camera.overview.width, 640);

  auto error = [](const std::string& text) {
    try {
      Scenario::parse(text + "robots:\n  - {team: 0, player: 1}\n", "bad.yaml");
    } catch (const simswift::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // Each camera its own; an unnamed one keeps the default.
  const Scenario pair = Scenario::parse("camera: {resolution: {top: 1280x960}}\nrobots:\n  - {team: 0, player: 1}\n",
                                        "pair.yaml");
  EXPECT_EQ(pair.camera.resolution[0], (al::ImageSize{1280, 960}));
  EXPECT_EQ(pair.camera.resolution[1], (al::ImageSize{640, 480}));
  EXPECT_EQ(Scenario().camera.resolution[0], (al::ImageSize{640, 480}));

  // Errors name the file, the line and the key.
  EXPECT_NE(error("camera: {resolution: 800x600}\n").find("bad.yaml:1"), std::string::npos);
  EXPECT_NE(error("camera: {resolution: 800x600}\n").find("resolution"), std::string::npos);
  EXPECT_NE(error("camera:\n  resolution: {top: 1280x960, bottom: 320x240}\n").find("bad.yaml:2"),
            std::string::npos);
  EXPECT_NE(error("camera:\n  resolution: {top: 1280x960, bottom: 320x240}\n").find("resolution.bottom"),
            std::string::npos);
  EXPECT_NE(error("camera: {resolution: {top: 1280x960, side: 640x480}}\n").find("side"), std::string::npos);
  EXPECT_NE(error("camera: {resolution: [1280, 960]}\n").find("resolution"), std::string::npos);
  EXPECT_NE(error("camera: {enabled: on, fps: 30}\n").find("fps"), std::string::npos);
  EXPECT_NE(error("camera: {overview: {robot: 3}}\n").find("robot"), std::string::npos);
  EXPECT_NE(error("camera: {overview: {mode: sky}}\n").find("mode"), std::string::npos);
}

}  // namespace

#endif  // SIMSWIFT_HAVE_CAMERAS

// A build without OSMesa has the null cameras (sim/runner/RunCameras.hpp):
// a scenario asking for rendering is refused before the first tick.
#include <gtest/gtest.h>

#include <string>

#include "sim/runner/Runner.hpp"

TEST(RunnerNullCameras, AScenarioAskingForCamerasIsRefused) {
  using simswift::runner::Runner;
  if (Runner::camerasAvailable()) GTEST_SKIP() << "this build renders (SIMSWIFT_CAMERAS=ON)";
  Runner r(simswift::runner::Scenario::parse(
      "duration: 0.1\ncamera: {enabled: on}\nrobots:\n  - {team: 0, player: 1}\n", "nullcam.yaml"));
  try {
    r.start();
    ADD_FAILURE() << "started";
  } catch (const simswift::runner::RunnerError& e) {
    EXPECT_NE(std::string(e.what()).find("built without cameras"), std::string::npos) << e.what();
  }
  EXPECT_EQ(r.framesDumped(), 0);
}
