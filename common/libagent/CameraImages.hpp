// Camera images next to the libagent block: what the NAO's two cameras see,
// filled by the simulator when rendering is on (see CameraShared.hpp for the
// frame handshake: `CameraFrame::images_valid` says whether this block holds
// the current frame's pictures).
//
// Each camera has its own resolution, 640x480 (default) or 1280x960: a NAO
// V6 program of rUNSWift's 2019-2022 releases reads the top camera at
// 1280x960 and the bottom at 640x480 (rUNSWift 2022,
// robot/perception/vision/VisionDefinitions.hpp). The buffers are sized for
// the largest; each image fills the start of its camera's buffers.
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

// Shared-memory name: SharedNames.hpp (RobotNames::images). Its layout is
// covered by SimExtension.hpp's kExtensionVersion.

// One camera's image size, px. The default is the NAO driver's 640x480.
struct ImageSize {
  int32_t width = 640, height = 480;
  bool operator==(const ImageSize& o) const { return width == o.width && height == o.height; }
  bool operator!=(const ImageSize& o) const { return !(*this == o); }
};

struct CameraImages {
  uint32_t magic;
  ImageSize size[kNumCameras];  // px, each camera's current resolution
  int64_t frame_index;      // frame these images belong to (0, 1, ... at 30 Hz)
  int64_t sim_time_us;      // simulated time they were rendered
  int32_t valid[kNumCameras];
  uint8_t yuv422[kNumCameras][kMaxImageWidth * kMaxImageHeight * 2];
  uint8_t rgb[kNumCameras][kMaxImageWidth * kMaxImageHeight * 3];

  // Bytes used in camera c's buffers at its current resolution.
  int64_t yuvBytes(int c) const { return int64_t(size[c].width) * size[c].height * 2; }
  int64_t rgbBytes(int c) const { return int64_t(size[c].width) * size[c].height * 3; }
};

}  // namespace common::libagent
