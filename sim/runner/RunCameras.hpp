// The rendering a run asks for (the scenario's camera:, --dump-frames,
// --overview): each robot's cameras into its images block, frame dumps and
// the overview sequence. A build with OSMesa (SIMSWIFT_CAMERAS=ON) renders
// with sim/camera (RenderedCameras.cpp); a build without has the null
// cameras (NullCameras.cpp), which render nothing: the Runner refuses a
// scenario asking for rendering there before it makes any (CMake compiles
// one of the two files).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "common/libagent/CameraImages.hpp"
#include "common/nao/NaoFacts.hpp"
#include "sim/runner/Scenario.hpp"
#include "sim/world/World.hpp"

namespace simswift::runner {

class RunCameras {
 public:
  virtual ~RunCameras() = default;
  // Renders robot `robot`'s two cameras into `images` for camera frame
  // `frame` (taken at t_us, simulated) if anyone wants them: the robot's
  // program (`for_program`) or the frame dump (robot named `team`,
  // `player` in the PNGs' names). True if `images` now holds this frame.
  virtual bool renderRobot(const World& world, int robot, int team, int player, bool for_program,
                           common::libagent::CameraImages& images, int64_t frame, int64_t t_us) = 0;
  // Renders robot `robot`'s camera `camera` (0 top, 1 bottom) alone at
  // `size` into `yuyv` (YUYV, size's bytes): a V4L2 device's frame.
  virtual void renderCamera(const World& world, int robot, int camera, common::libagent::ImageSize size,
                            uint8_t* yuyv) = 0;
  // After each World::step(): the overview's frame, if one is due.
  virtual void captureOverview(const World& world) = 0;
  virtual int64_t framesDumped() const = 0;    // PNGs written by --dump-frames
  virtual int64_t overviewFrames() const = 0;  // overview PNGs written
  // Ends the overview (assembles its video, once); its message, empty if none.
  virtual std::string finishOverview() = 0;
};

// Whether this build renders (OSMesa).
bool camerasAvailable();

// The run's cameras as `spec` asks, through `lens` (the robots' kind);
// `colour_of_robot`: each World robot's jersey (its side, 0 blue, 1 red).
std::unique_ptr<RunCameras> makeRunCameras(const World& world, const CameraSpec& spec,
                                           const common::nao::CameraLens& lens, std::vector<int> colour_of_robot);

}  // namespace simswift::runner
