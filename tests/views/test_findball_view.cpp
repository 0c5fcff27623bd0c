// The FindBall view: a PNG for a known distribution has the expected colour
// in a chosen segment's pixel and the robot circle where the pose says.
#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "agent/behaviour/PositionalDistribution.hpp"
#include "sim/programs/FindBallObserver.hpp"
#include "sim/views/FindBallView.hpp"

using sim::views::FindBallView;
using sim::views::FindBallViewData;
using sim::views::Rgb;

namespace {

struct Png {
  cairo_surface_t* s = nullptr;
  explicit Png(const std::string& path) : s(cairo_image_surface_create_from_png(path.c_str())) {}
  ~Png() { cairo_surface_destroy(s); }
  bool ok() const { return cairo_surface_status(s) == CAIRO_STATUS_SUCCESS; }
  int width() const { return cairo_image_surface_get_width(s); }
  int height() const { return cairo_image_surface_get_height(s); }
  // 0..255 per channel at pixel (x, y).
  void rgb(int x, int y, int* r, int* g, int* b) const {
    cairo_surface_flush(s);
    const unsigned char* row = cairo_image_surface_get_data(s) + y * cairo_image_surface_get_stride(s);
    const uint32_t px = reinterpret_cast<const uint32_t*>(row)[x];
    *r = (px >> 16) & 0xff;
    *g = (px >> 8) & 0xff;
    *b = px & 0xff;
  }
};

// Expects the pixel under field point (fx, fy) mm to have colour c (+-2/255).
void expectColourAt(const Png& png, const FindBallView& view, const FindBallViewData& d,
                    double fx, double fy, Rgb c, const char* what) {
  double px, py;
  view.toPixel(d, fx, fy, &px, &py);
  int r, g, b;
  png.rgb(static_cast<int>(px), static_cast<int>(py), &r, &g, &b);
  EXPECT_NEAR(r, std::lround(c.r * 255), 2) << what;
  EXPECT_NEAR(g, std::lround(c.g * 255), 2) << what;
  EXPECT_NEAR(b, std::lround(c.b * 255), 2) << what;
}

FindBallViewData sampleData() {
  agent::behaviour::PositionalDistribution p;  // 3 x 3 over 9000 x 6000
  p.set({0.05, 0.05, 0.60, 0.05, 0.05, 0.05, 0.05, 0.05, 0.05});
  FindBallViewData d;
  simswift::programs::setDistribution(d, p);
  sim::views::ViewRobot self;
  self.player = 2;
  self.x = -2000;
  self.y = -1000;
  self.theta = 0;
  self.self = true;
  self.has_target = true;
  self.target_x = 0;
  self.target_y = 2000;
  sim::views::ViewRobot mate;
  mate.player = 3;
  mate.x = 1000;
  mate.y = -2000;
  mate.theta = 1.0;
  mate.has_target = true;
  mate.target_x = 3000;
  mate.target_y = 0;
  d.robots = {self, mate};
  d.caption = "t=12.0 s  robot 2 (team distribution)";
  return d;
}

}  // namespace

TEST(FindBallView, SegmentColourScale) {
  const Rgb zero = FindBallView::segmentColour(0.0, 9);
  const Rgb uniform = FindBallView::segmentColour(1.0 / 9, 9);
  const Rgb likely = FindBallView::segmentColour(0.5, 9);
  EXPECT_GT(zero.g, 0.5);
  EXPECT_EQ(zero.r, 0.0);  // green
  EXPECT_NEAR(uniform.r, 0.9, 1e-12);
  EXPECT_NEAR(uniform.g, 0.75, 1e-12);  // yellow
  EXPECT_NEAR(likely.r, 0.9, 1e-12);
  EXPECT_EQ(likely.g, 0.0);  // red
}

TEST(FindBallView, PngShowsSegmentsAndRobotsWhereTheDataSay) {
  const FindBallView view(0.08);
  const FindBallViewData d = sampleData();
  const std::string path = std::string(SIMSWIFT_BINARY_DIR) + "/test_findball_view.png";
  std::string err;
  ASSERT_TRUE(view.writePng(d, path, &err)) << err;
  Png png(path);
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.width(), 832);  // (9000 + 2 x 700) mm x 0.08 px/mm
  EXPECT_EQ(png.height(), 592);

  // Segment 3 (top right, 0.6): red; away from lines and robots.
  expectColourAt(png, view, d, 3500, 2500, FindBallView::segmentColour(0.6, 9), "segment 3");
  expectColourAt(png, view, d, 3500, 2500, Rgb{0.9, 0.0, 0.0}, "segment 3 is red");
  // Segment 7 (bottom left, 0.05): green-yellow.
  expectColourAt(png, view, d, -2600, -2400, FindBallView::segmentColour(0.05, 9), "segment 7");
  // The robot: blue disc at its pose (80 mm off its heading line), and
  // 250 mm away on the side away from its arrow the segment shows again.
  expectColourAt(png, view, d, -2000, -920, FindBallView::selfColour(), "robot 2 disc");
  expectColourAt(png, view, d, -2000, -1080, FindBallView::selfColour(), "robot 2 disc");
  expectColourAt(png, view, d, -2200, -1150, FindBallView::segmentColour(0.05, 9),
                 "beside robot 2");
  // The teammate: white disc.
  expectColourAt(png, view, d, 950, -1920, FindBallView::teammateColour(), "robot 3 disc");
  // Its search point is a ring: centre shows the segment (6, 0.05), rim the teammate colour.
  expectColourAt(png, view, d, 3000, 0, FindBallView::segmentColour(0.05, 9), "point centre");
  expectColourAt(png, view, d, 3000, -120, FindBallView::teammateColour(), "point rim");
}

TEST(FindBallView, BadDataIsAnErrorNotACrash) {
  const FindBallView view;
  FindBallViewData d = sampleData();
  d.probabilities.pop_back();
  std::string err;
  EXPECT_FALSE(view.writePng(d, std::string(SIMSWIFT_BINARY_DIR) + "/x.png", &err));
  EXPECT_NE(err.find("3 x 3 grid"), std::string::npos) << err;
  d = sampleData();
  EXPECT_FALSE(view.writePng(d, "/nonexistent-dir/view.png", &err));
  EXPECT_NE(err.find("cannot write"), std::string::npos) << err;
}
