// The run's cameras rendered with OSMesa (sim/camera; CMake compiles this
// file when SIMSWIFT_CAMERAS=ON, NullCameras.cpp otherwise).
#include <utility>
#include <vector>

#include "sim/camera/FrameDumper.hpp"
#include "sim/camera/Overview.hpp"
#include "sim/camera/RobotCameras.hpp"
#include "sim/runner/RunCameras.hpp"

namespace simswift::runner {

namespace {

namespace al = common::libagent;

camera::OverviewConfig overviewConfig(const CameraSpec::Overview& ov) {
  camera::OverviewConfig oc;
  using M = CameraSpec::Overview::Mode;
  oc.mode = ov.mode == M::Fixed   ? camera::OverviewConfig::Mode::Fixed
            : ov.mode == M::Robot ? camera::OverviewConfig::Mode::FollowRobot
                                  : camera::OverviewConfig::Mode::FollowBall;
  oc.robot = ov.robot;
  oc.rate_hz = ov.rate_hz;
  oc.width = ov.width;
  oc.height = ov.height;
  oc.dir = ov.dir;
  return oc;
}

class RenderedCameras final : public RunCameras {
 public:
  RenderedCameras(const World& world, const CameraSpec& spec, const common::nao::CameraLens& lens,
                  std::vector<int> colour_of_robot)
      : cameras_(world, config(spec, lens)) {
    cameras_.setTeams(std::move(colour_of_robot));  // jerseys by side, whatever the SPL team numbers
    if (!spec.dump_dir.empty()) dumper_ = std::make_unique<camera::FrameDumper>(spec.dump_dir, spec.dump_every);
    if (spec.overview.enabled) overview_ = std::make_unique<camera::OverviewCamera>(overviewConfig(spec.overview));
  }

  bool renderRobot(const World& world, int robot, int team, int player, bool for_program, al::CameraImages& images,
                   int64_t frame, int64_t t_us) override {
    const bool dump = dumper_ && dumper_->wants(frame);
    if (!for_program && !dump) return false;
    cameras_.fillImages(world, robot, images, frame, t_us);
    if (dump) dumper_->dump(team, player, images);
    return true;
  }

  void renderCamera(const World& world, int robot, int camera, al::ImageSize size, uint8_t* yuyv) override {
    rgb_.resize(static_cast<size_t>(size.width) * size.height * 3);
    cameras_.renderCamera(world, robot, static_cast<camera::CameraId>(camera), size, yuyv, rgb_.data());
  }

  void captureOverview(const World& world) override {
    if (overview_) overview_->maybeCapture(cameras_, world);
  }
  int64_t framesDumped() const override { return dumper_ ? dumper_->written() : 0; }
  int64_t overviewFrames() const override { return overview_ ? overview_->frames() : 0; }
  std::string finishOverview() override {
    if (overview_ && !overview_finished_) {
      overview_finished_ = true;
      overview_message_ = overview_->finish(overview_->config().dir + "/overview.mp4").message;
    }
    return overview_message_;
  }

 private:
  static camera::RobotCamerasConfig config(const CameraSpec& spec, const common::nao::CameraLens& lens) {
    camera::RobotCamerasConfig cc;
    for (int c = 0; c < al::kNumCameras; ++c) cc.resolution[c] = spec.resolution[c];
    cc.lens = lens;
    return cc;
  }

  camera::RobotCameras cameras_;
  std::unique_ptr<camera::FrameDumper> dumper_;
  std::vector<uint8_t> rgb_;  // renderCamera's scratch
  std::unique_ptr<camera::OverviewCamera> overview_;
  bool overview_finished_ = false;
  std::string overview_message_;
};

}  // namespace

bool camerasAvailable() { return true; }

std::unique_ptr<RunCameras> makeRunCameras(const World& world, const CameraSpec& spec,
                                           const common::nao::CameraLens& lens, std::vector<int> colour_of_robot) {
  return std::make_unique<RenderedCameras>(world, spec, lens, std::move(colour_of_robot));
}

}  // namespace simswift::runner
