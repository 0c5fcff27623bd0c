// A NAO V6's cameras reach its program as a V5's do: the builtin reference
// program on a LoLA body gets the 30 Hz frames and the rendered YUV422
// images through simswift's extension object beside its socket.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <string>

#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"

using simswift::runner::Runner;
using simswift::runner::Scenario;

TEST(V6Cameras, TheProgramGetsFramesAndRenderedImages) {
  const std::string socket = "/tmp/simswift-test-v6cam-" + std::to_string(::getpid());
  Runner r(Scenario::parse("duration: 1.0\nseed: 4\ncamera: {enabled: on, resolution: 640x480}\nrobots:\n"
                           "  - {team: 19, player: 1, x: -1.0, y: 0.0, lola: {socket: " +
                               socket + "}}\nball: {x: 0.0, y: 0.0}\n",
                           "v6cam.yaml"));
  simswift::runner::RunOptions o;
  o.progress = false;
  r.run(o);
  EXPECT_EQ(r.world().tickUs(), 12000);
  const agent::program::RobotProgram* p = r.programs().program(0);
  ASSERT_NE(p, nullptr);
  // 1.0 s is 83 ticks of 12 ms (0.996 s): frames 0..29 at 30 Hz, each
  // answered by the program's Perception.
  EXPECT_EQ(r.ticks(), 83);
  EXPECT_EQ(r.lastFrame(), 29);
  EXPECT_EQ(p->perceptionFrames(), 30);
  const common::libagent::CameraImages* im = r.images(0);
  ASSERT_NE(im, nullptr);
  EXPECT_EQ(im->magic, common::libagent::kCameraImagesMagic);
  EXPECT_EQ(im->size[0], (common::libagent::ImageSize{640, 480}));
  EXPECT_EQ(im->valid[0], 1);
  // A rendered field: not one flat colour.
  const uint8_t* y = im->yuv422[0];
  const auto [lo, hi] = std::minmax_element(y, y + im->yuvBytes(0));
  EXPECT_GT(*hi - *lo, 50);
}
