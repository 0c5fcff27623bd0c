// YUV422 (YUYV, BT.601 full range) conversion.
#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include "sim/camera/Yuv.hpp"

using namespace simswift::camera;

TEST(Yuv422, KnownColours) {
  // Two pixels per pair: white, white / red, red / mid grey, mid grey.
  const std::vector<uint8_t> rgb = {255, 255, 255, 255, 255, 255, 255, 0, 0, 255, 0, 0, 128, 128, 128, 128, 128, 128};
  std::vector<uint8_t> yuv(rgb.size() / 3 * 2);
  rgbToYuyv(rgb.data(), 6, 1, yuv.data());
  // White: Y 255, no chroma.
  EXPECT_EQ(yuv[0], 255); EXPECT_EQ(yuv[1], 128); EXPECT_EQ(yuv[2], 255); EXPECT_EQ(yuv[3], 128);
  // Red: Y = 0.299*255 = 76.2, U = 128 - 0.1687*255 = 85.0, V = 128 + 127.5 -> 255.
  EXPECT_EQ(yuv[4], 76); EXPECT_EQ(yuv[5], 85); EXPECT_EQ(yuv[6], 76); EXPECT_EQ(yuv[7], 255);
  // Grey: Y 128, no chroma.
  EXPECT_EQ(yuv[8], 128); EXPECT_EQ(yuv[9], 128); EXPECT_EQ(yuv[11], 128);
}

TEST(Yuv422, RoundTripOnASmoothImageWithinTwoLevels) {
  const int w = 640, h = 480;
  std::vector<uint8_t> rgb(size_t(w) * h * 3), yuv(size_t(w) * h * 2), back(rgb.size());
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      uint8_t* p = &rgb[(size_t(r) * w + c) * 3];
      p[0] = static_cast<uint8_t>(20 + c * 215 / (w - 1));           // smooth ramps, inside
      p[1] = static_cast<uint8_t>(20 + r * 215 / (h - 1));           // the range where no
      p[2] = static_cast<uint8_t>(60 + (c + r) * 130 / (w + h - 2)); // channel clips
    }
  rgbToYuyv(rgb.data(), w, h, yuv.data());
  yuyvToRgb(yuv.data(), w, h, back.data());
  int worst = 0;
  for (size_t i = 0; i < rgb.size(); ++i) worst = std::max(worst, std::abs(int(rgb[i]) - int(back[i])));
  EXPECT_LE(worst, 2);
  EXPECT_GE(worst, 1);  // chroma subsampling and rounding do lose something
}

TEST(Yuv422, OddWidthIsRejected) {
  std::vector<uint8_t> rgb(9), yuv(6);
  EXPECT_THROW(rgbToYuyv(rgb.data(), 3, 1, yuv.data()), std::invalid_argument);
}
