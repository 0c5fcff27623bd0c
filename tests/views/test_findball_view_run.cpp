// The view fed from running behaviours (kinematic stand-in, no physics):
// three robots running the 2017 component, one frame every 5 s written to
// build/findball_view_demo/; each frame's robot disc and its teammates'
// discs are where the poses say.
#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "sim/programs/FindBallObserver.hpp"
#include "sim/views/FindBallView.hpp"
#include "harness/KinematicWorld.hpp"

using namespace agent::behaviour;

TEST(FindBallViewRun, FramesFromThreeSearchingRobots) {
  const std::string dir = std::string(SIMSWIFT_BINARY_DIR) + "/findball_view_demo";
  std::filesystem::create_directories(dir);
  kin::World w;
  w.ball = {4000, -2500};  // table 5.2's position 2
  BehaviourConfig c;
  w.add(2, {-3250, 3000, -kPi / 2}, c);
  w.add(3, {-2000, -3000, kPi / 2}, c);
  w.add(4, {-1750, 3000, -kPi / 2}, c);
  const sim::views::FindBallView view(0.08);
  int frames = 0;
  for (int k = 0; k <= 30 * 30; ++k) {
    w.step();
    if (k % 150 != 0) continue;
    for (size_t i = 0; i < w.robots.size(); ++i) {
      const auto& r = w.robots[i];
      const BehaviourInputs in = w.inputsFor(r);
      const auto d = simswift::programs::robotView(in, *r.behaviour);
      ASSERT_EQ(d.robots.size(), 3u);
      char name[64];
      std::snprintf(name, sizeof name, "/robot%d_%04d.png", r.player, frames);
      std::string err;
      ASSERT_TRUE(view.writePng(d, dir + name, &err)) << err;
      // Check the robot's own disc (80 mm beside its heading line).
      cairo_surface_t* s = cairo_image_surface_create_from_png((dir + name).c_str());
      ASSERT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
      double px, py;
      view.toPixel(d, r.pose.x - 80 * std::sin(r.pose.theta), r.pose.y + 80 * std::cos(r.pose.theta),
                   &px, &py);
      const unsigned char* row =
          cairo_image_surface_get_data(s) + static_cast<int>(py) * cairo_image_surface_get_stride(s);
      const uint32_t p = reinterpret_cast<const uint32_t*>(row)[static_cast<int>(px)];
      EXPECT_NEAR(static_cast<int>(p & 0xff), 255, 2) << name;            // blue
      EXPECT_NEAR(static_cast<int>((p >> 16) & 0xff), 38, 2) << name;     // red
      cairo_surface_destroy(s);
    }
    ++frames;
  }
  EXPECT_EQ(frames, 7);
}
