// FindBall view frames from a robot's findball Blackboard section: frames
// at the asked rate of simulated time, one folder per behaving robot, the
// section's team distribution and pose where they should be in the PNG.
#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "sim/programs/FindBallObserver.hpp"
#include "sim/views/FindBallRecorder.hpp"

using sim::views::FindBallView;

TEST(FindBallRecorder, FramesAtTheRateFromTheSection) {
  const std::string dir = std::string(SIMSWIFT_BINARY_DIR) + "/test_findball_recorder";
  std::filesystem::remove_all(dir);
  agent::blackboard::FindBallInfo on;
  on.active = true;
  on.kind = 1;
  on.columns = 3;
  on.rows = 3;
  on.team = {0.05, 0.05, 0.60, 0.05, 0.05, 0.05, 0.05, 0.05, 0.05};  // segment 3: top right
  on.pose_x = -2000;
  on.pose_y = -1000;
  on.has_point = true;
  on.point_x = 0;
  on.point_y = 2000;
  agent::blackboard::FindBallInfo off;  // a scripted robot: no section
  sim::views::FindBallRecorderConfig c;
  c.dir = dir;
  c.rate_hz = 2;
  sim::views::FindBallRecorder rec(c, {"t19p2", "t19p3"}, {2, 3});
  // What the program side's observer hook gives for the two sections.
  const std::vector<std::optional<sim::views::FindBallViewData>> views = {
      simswift::programs::observedView(on, 2, "t19p2"), simswift::programs::observedView(off, 3, "t19p3")};
  for (int64_t t_us = 0; t_us <= 1000000; t_us += 10000) rec.maybeCapture(t_us, views);
  EXPECT_EQ(rec.frames(), 3);  // t = 0, 0.5, 1.0 s
  EXPECT_TRUE(std::filesystem::exists(dir + "/t19p2/findball_000002.png"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/t19p3"));

  const sim::views::FindBallViewData d = simswift::programs::viewFromInfo(on, 2, "t19p2");
  cairo_surface_t* s = cairo_image_surface_create_from_png((dir + "/t19p2/findball_000001.png").c_str());
  ASSERT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
  FindBallView view;
  auto expectAt = [&](double fx, double fy, sim::views::Rgb c, const char* what) {
    double px, py;
    view.toPixel(d, fx, fy, &px, &py);
    cairo_surface_flush(s);
    const unsigned char* row = cairo_image_surface_get_data(s) + static_cast<int>(py) * cairo_image_surface_get_stride(s);
    const uint32_t v = reinterpret_cast<const uint32_t*>(row)[static_cast<int>(px)];
    EXPECT_NEAR((v >> 16) & 0xff, std::lround(c.r * 255), 2) << what;
    EXPECT_NEAR((v >> 8) & 0xff, std::lround(c.g * 255), 2) << what;
    EXPECT_NEAR(v & 0xff, std::lround(c.b * 255), 2) << what;
  };
  expectAt(3500, 2700, FindBallView::segmentColour(0.60, 9), "segment 3");
  expectAt(-3500, -2700, FindBallView::segmentColour(0.05, 9), "segment 7");
  expectAt(-2000, -920, FindBallView::selfColour(), "the robot's disc at its pose");
  expectAt(-2000, -1080, FindBallView::selfColour(), "the robot's disc at its pose");
  cairo_surface_destroy(s);
  EXPECT_NE(rec.finish().find("t19p2: 3 FindBall view frames"), std::string::npos);
}
