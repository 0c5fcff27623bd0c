// Camera rendering throughput:
//  - frames per second of one NAO camera (render + YUYV conversion) at
//    640x480 and 1280x960, on one core (LP_NUM_THREADS=1, see Renderer.hpp);
//  - real-time factor of one robot stepping physics at 100 Hz and rendering
//    both cameras at 30 Hz of simulated time, both at 640x480, then the NAO
//    V6 pair (top 1280x960, bottom 640x480), with that pair's frames (both
//    cameras) per second of rendering.
// Usage: bench_camera [--out FILE] [--frames N] [--seconds S]
// Wall-clock time is measured here only; the simulation itself never reads it.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "BenchResults.hpp"
#include "BenchSetup.hpp"
#include "sim/camera/RobotCameras.hpp"
#include "sim/camera/Yuv.hpp"
#include "sim/world/World.hpp"

using namespace simswift;
using namespace simswift::camera;
using bench::Clock;
using bench::seconds;

int main(int argc, char** argv) {
  bench::FrameArgs args;  // --frames default 300
  if (!bench::parseFrameArgs(argc, argv, &args)) return 2;
  const std::string& out = args.out;
  const int frames = args.frames;
  const double sim_seconds = args.sim_seconds;

  const auto model = bench::loadNao();
  const auto q = bench::standingPosture(*model);

  // --- One camera: a game-like view (field, goal, another robot, ball).
  {
    World world(FieldConfig::spl2017());
    world.addRobot(model, -1.0, 0.0, 0.0, q);
    world.addRobot(model, 0.5, 0.3, M_PI, q);
    world.placeBall(0.0, -0.2);
    RobotCameras cams(world);
    cams.setTeams({0, 1});
    cams.syncScene(world);
    std::printf("renderer: %s, LP_NUM_THREADS=%s\n", Renderer::rendererName(),
                std::getenv("LP_NUM_THREADS") ? std::getenv("LP_NUM_THREADS") : "(unset)");
    for (int w : {640, 1280}) {
      const int h = w * 3 / 4;
      cams.setResolution({w, h});
      const CameraView view = cams.view(world, 0, kTop);
      std::vector<uint8_t> rgb(size_t(w) * h * 3), yuv(size_t(w) * h * 2);
      cams.renderer().render(cams.scene(), view, rgb.data());  // warm-up: display lists, buffers
      const int n = w == 640 ? frames : std::max(frames / 3, 10);
      const auto t0 = Clock::now();
      for (int i = 0; i < n; ++i) {
        cams.renderer().render(cams.scene(), view, rgb.data());
        rgbToYuyv(rgb.data(), w, h, yuv.data());
      }
      const double fps = n / seconds(t0, Clock::now());
      bench::report("camera_fps_" + std::to_string(w) + "x" + std::to_string(h), fps, "fps", out.c_str());
    }
  }

  // --- One robot: physics every 10 ms, both cameras at 30 Hz: both at
  // 640x480, then the NAO V6 pair of rUNSWift 2019-2022 (top 1280x960,
  // bottom 640x480; rUNSWift 2022 robot/perception/vision/VisionDefinitions.hpp).
  const common::libagent::ImageSize small{640, 480}, large{1280, 960};
  struct Pair { const char* name; common::libagent::ImageSize top, bottom; };
  for (const Pair& pair : {Pair{"", small, small}, Pair{"_v6pair", large, small}}) {
    World world(FieldConfig::spl2017());
    const int r = world.addRobot(model, -1.0, 0.0, 0.0, q);
    world.robot(r).holdPosture(q);
    world.placeBall(0.0, 0.0);
    world.setBallVelocity({-0.5, 0.1, 0});
    RobotCamerasConfig cc;
    cc.resolution[kTop] = pair.top;
    cc.resolution[kBottom] = pair.bottom;
    RobotCameras cams(world, cc);
    auto images = std::make_unique<common::libagent::CameraImages>();
    const int64_t ticks = common::nao::ticksIn(sim_seconds);
    int64_t next_frame = 0, rendered = 0;
    double render_wall = 0;  // s spent in fillImages
    const auto t0 = Clock::now();
    for (int64_t t = 0; t < ticks; ++t) {
      world.step();
      // Frame k is due at k/30 s of simulated time.
      if (world.time() + 1e-9 >= next_frame / 30.0) {
        const auto f0 = Clock::now();
        cams.fillImages(world, r, *images, next_frame);
        render_wall += seconds(f0, Clock::now());
        ++next_frame;
        ++rendered;
      }
    }
    const double wall = seconds(t0, Clock::now());
    if (*pair.name)  // both cameras of one frame per second of wall time
      bench::report(std::string("camera_fps") + pair.name + "_both", rendered / render_wall, "fps", out.c_str());
    bench::report(std::string("camera_rtf_1robot_2cams_30hz") + pair.name, (ticks * kTickSeconds) / wall, "x",
                  out.c_str());
    std::printf("(%dx%d top, %dx%d bottom: %lld camera frames in %.2f s simulated, %.2f s wall)\n", pair.top.width,
                pair.top.height, pair.bottom.width, pair.bottom.height, static_cast<long long>(rendered),
                ticks * kTickSeconds, wall);
  }
  return 0;
}
