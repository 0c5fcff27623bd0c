// The null cameras of a build without OSMesa (SIMSWIFT_CAMERAS=OFF; CMake
// compiles this file instead of RenderedCameras.cpp): nothing is rendered.
#include "sim/runner/RunCameras.hpp"

namespace simswift::runner {

namespace {

class NullCameras final : public RunCameras {
 public:
  bool renderRobot(const World&, int, int, int, bool, common::libagent::CameraImages&, int64_t, int64_t) override {
    return false;
  }
  // Never called: the Runner serves no V4L2 cameras without rendering.
  void renderCamera(const World&, int, int, common::libagent::ImageSize, uint8_t*) override {}
  void captureOverview(const World&) override {}
  int64_t framesDumped() const override { return 0; }
  int64_t overviewFrames() const override { return 0; }
  std::string finishOverview() override { return {}; }
};

}  // namespace

bool camerasAvailable() { return false; }

std::unique_ptr<RunCameras> makeRunCameras(const World&, const CameraSpec&, const common::nao::CameraLens&,
                                           std::vector<int>) {
  return std::make_unique<NullCameras>();
}

}  // namespace simswift::runner
