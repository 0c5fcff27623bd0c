// Shared helpers for the camera tests: image measurements and an analytic
// reference for the ball's image.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/camera/CameraModel.hpp"

namespace camtest {

using simswift::camera::CameraModel;

inline const uint8_t* px(const std::vector<uint8_t>& img, int w, int col, int row) {
  return img.data() + (size_t(row) * w + col) * 3;
}

// The carpet: green clearly dominant.
inline bool isGreen(const uint8_t* p) { return p[1] > p[0] + 40 && p[1] > p[2] + 40; }
// The test sky: pure blue (see testOptions()).
inline bool isBlue(const uint8_t* p) { return p[2] > 200 && p[0] < 30 && p[1] < 30; }
// The ball: its black patches and (shaded) white, i.e. grey of any brightness.
inline bool isBallColour(const uint8_t* p) {
  const int lo = std::min({p[0], p[1], p[2]}), hi = std::max({p[0], p[1], p[2]});
  return hi - lo < 25;
}

struct Blob {
  double u = 0, v = 0;  // centroid (continuous pixel coordinates)
  int64_t area = 0;     // pixels
};

// Centroid of the pixels in [c0,c1) x [r0,r1) for which `pred` holds.
template <typename Pred>
Blob blob(const std::vector<uint8_t>& img, int w, int h, Pred pred, int c0 = 0, int r0 = 0, int c1 = -1,
          int r1 = -1) {
  if (c1 < 0) c1 = w;
  if (r1 < 0) r1 = h;
  c0 = std::max(c0, 0), r0 = std::max(r0, 0), c1 = std::min(c1, w), r1 = std::min(r1, h);
  Blob b;
  double su = 0, sv = 0;
  for (int r = r0; r < r1; ++r)
    for (int c = c0; c < c1; ++c)
      if (pred(px(img, w, c, r))) {
        su += c + 0.5;
        sv += r + 0.5;
        ++b.area;
      }
  if (b.area) b.u = su / b.area, b.v = sv / b.area;
  return b;
}

// The exact perspective image of a sphere, sampled at pixel centres like the
// rasteriser: a pixel belongs to it if the ray through its centre hits the
// sphere. Its centroid is where the ball "should" appear; it differs from
// project(centre) by up to a few px for a close ball far off-axis.
inline Blob sphereImage(const CameraModel& cam, const Eigen::Vector3d& centre, double radius) {
  const int w = cam.intrinsics.width, h = cam.intrinsics.height;
  const Eigen::Vector3d o = cam.pose.translation();
  Blob b;
  double su = 0, sv = 0;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const Eigen::Vector3d d = cam.rayDirection(c + 0.5, r + 0.5);
      const Eigen::Vector3d oc = centre - o;
      const double t = oc.dot(d);
      if (t > 0 && (oc - t * d).squaredNorm() < radius * radius) {
        su += c + 0.5;
        sv += r + 0.5;
        ++b.area;
      }
    }
  if (b.area) b.u = su / b.area, b.v = sv / b.area;
  return b;
}

// The ball in a window around where the model expects it (other grey or
// white things -- goals, robots -- may be elsewhere in the picture).
inline Blob ballNear(const std::vector<uint8_t>& img, int w, int h, const Blob& expected) {
  const int half = static_cast<int>(std::sqrt(double(expected.area))) + 12;
  const int cu = static_cast<int>(expected.u), cv = static_cast<int>(expected.v);
  return blob(img, w, h, isBallColour, cu - half, cv - half, cu + half, cv + half);
}

inline uint64_t fnv1a(const uint8_t* data, size_t n) {
  uint64_t h = 1469598103934665603ull;
  for (size_t i = 0; i < n; ++i) h = (h ^ data[i]) * 1099511628211ull;
  return h;
}
inline uint64_t fnv1a(const std::vector<uint8_t>& v) { return fnv1a(v.data(), v.size()); }

// A fresh, empty output folder under the build tree.
inline std::string freshDir(const std::string& name) {
  const std::string d = std::string(SIMSWIFT_BINARY_DIR) + "/test-camera-out/" + name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// CI has no display: every camera test renders with DISPLAY unset.
inline void noDisplay() { unsetenv("DISPLAY"); }

}  // namespace camtest
