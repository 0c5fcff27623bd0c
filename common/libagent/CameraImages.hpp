// Camera images next to the libagent block: what the NAO's two cameras see,
// filled by the simulator when rendering is on (see CameraShared.hpp for the
// frame handshake: `CameraFrame::images_valid` says whether this block holds
// the current frame's pictures).
//
// Both cameras always share one resolution, 640x480 (default) or 1280x960.
// Rows are stored top row first, pixels left to right, tightly packed:
//  - yuv422: YUYV as the NAO's driver delivers it (4 bytes per 2 pixels:
//    Y0 U Y1 V, U and V shared by the pixel pair), BT.601 full range
//    (JPEG convention, 0..255 for Y, U, V with 128 = no chroma);
//  - rgb: 3 bytes per pixel, the renderer's output before conversion.
// Index 0 is the top camera, 1 the bottom camera.
#pragma once

#include <cstdint>

namespace common::libagent {

constexpr int kMaxImageWidth = 1280;
constexpr int kMaxImageHeight = 960;
constexpr int kNumCameras = 2;  // 0 = top, 1 = bottom
constexpr uint32_t kCameraImagesMagic = 0x53574349;  // "SWCI"

// Shared-memory name: SharedNames.hpp (RobotNames::images).

struct CameraImages {
  uint32_t magic;
  int32_t width, height;    // px, current resolution of both cameras
  int64_t frame_index;      // frame these images belong to (0, 1, ... at 30 Hz)
  int64_t sim_time_us;      // simulated time they were rendered
  int32_t valid[kNumCameras];
  uint8_t yuv422[kNumCameras][kMaxImageWidth * kMaxImageHeight * 2];
  uint8_t rgb[kNumCameras][kMaxImageWidth * kMaxImageHeight * 3];

  // Bytes used in each buffer at the current resolution.
  int64_t yuvBytes() const { return int64_t(width) * height * 2; }
  int64_t rgbBytes() const { return int64_t(width) * height * 3; }
};

}  // namespace common::libagent
