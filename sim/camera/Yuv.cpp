#include "sim/camera/Yuv.hpp"

#include <stdexcept>

namespace simswift::camera {

namespace {
// BT.601 full-range coefficients scaled by 2^16 and rounded.
constexpr int32_t kOne = 1 << 16;
constexpr int32_t kHalf = 1 << 15;
constexpr int32_t kYR = 19595, kYG = 38470, kYB = 7471;           // 0.299, 0.587, 0.114
constexpr int32_t kUR = -11059, kUG = -21709, kUB = 32768;        // -0.168736, -0.331264, 0.5
constexpr int32_t kVR = 32768, kVG = -27439, kVB = -5329;         // 0.5, -0.418688, -0.081312
constexpr int32_t kRV = 91881;                                    // 1.402
constexpr int32_t kGU = -22554, kGV = -46802;                     // -0.344136, -0.714136
constexpr int32_t kBU = 116130;                                   // 1.772

inline uint8_t clamp8(int32_t v) { return static_cast<uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v)); }
// Rounds a value carrying 16 fractional bits to the nearest integer
// (arithmetic shift on the biased value: exact for negatives too).
inline int32_t round16(int32_t v) { return (v + kHalf) >> 16; }
}  // namespace

void rgbToYuyv(const uint8_t* rgb, int width, int height, uint8_t* yuyv) {
  if (width % 2 != 0) throw std::invalid_argument("rgbToYuyv: width must be even");
  const int64_t pairs = int64_t(width) * height / 2;
  for (int64_t i = 0; i < pairs; ++i) {
    const uint8_t* p = rgb + i * 6;
    uint8_t* q = yuyv + i * 4;
    const int32_t r0 = p[0], g0 = p[1], b0 = p[2], r1 = p[3], g1 = p[4], b1 = p[5];
    // Chroma from the pair's sum: coefficients halved by shifting one bit more.
    const int32_t rs = r0 + r1, gs = g0 + g1, bs = b0 + b1;
    q[0] = clamp8(round16(kYR * r0 + kYG * g0 + kYB * b0));
    q[1] = clamp8(128 + ((kUR * rs + kUG * gs + kUB * bs + kOne) >> 17));
    q[2] = clamp8(round16(kYR * r1 + kYG * g1 + kYB * b1));
    q[3] = clamp8(128 + ((kVR * rs + kVG * gs + kVB * bs + kOne) >> 17));
  }
}

void yuyvToRgb(const uint8_t* yuyv, int width, int height, uint8_t* rgb) {
  if (width % 2 != 0) throw std::invalid_argument("yuyvToRgb: width must be even");
  const int64_t pairs = int64_t(width) * height / 2;
  for (int64_t i = 0; i < pairs; ++i) {
    const uint8_t* q = yuyv + i * 4;
    uint8_t* p = rgb + i * 6;
    const int32_t u = q[1] - 128, v = q[3] - 128;
    const int32_t dr = kRV * v, dg = kGU * u + kGV * v, db = kBU * u;
    for (int k = 0; k < 2; ++k) {
      const int32_t y = int32_t(q[k * 2]) << 16;
      p[k * 3 + 0] = clamp8(round16(y + dr));
      p[k * 3 + 1] = clamp8(round16(y + dg));
      p[k * 3 + 2] = clamp8(round16(y + db));
    }
  }
}

}  // namespace simswift::camera
