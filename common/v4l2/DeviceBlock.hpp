// A robot's two cameras as V4L2 devices: what the simulator (sim/bridge/
// V4l2Devices) and the shim preloaded into a launched program (shim/V4l2Device.cpp)
// share. An unchanged program opens /dev/video-top (its V4L2 calls are
// answered by the shim, docs/porting.md section 3); the frames, and what the
// program asks of them, cross here:
//
//  - a shared-memory object, DeviceBlock (its name in the program's
//    environment, kBlockVariable), both sides map it read-write;
//  - three FIFOs beside it in /dev/shm (fifoPath): per camera "ready" (the
//    simulator writes a byte per frame published: the program's camera fd
//    IS that FIFO's read end, so poll/select/epoll on it wait in the kernel,
//    unchanged), and one "taken" (the shim writes a byte when a frame was
//    dequeued: the simulator's lock-step wait; its hang-up says the program
//    is gone).
//
// Lock-step: a frame is taken when the program dequeues it (VIDIOC_DQBUF);
// the simulator publishes camera frame k at its 30 Hz tick and does not run
// the next tick until every camera it published k to has had k dequeued (or
// stopped streaming). The rest of what the program does with the frame runs
// beside the following ticks.
//
// The simulator never trusts what the program writes (it may write anything
// into a shared block): it reads each program field once per frame and
// checks it (sim/bridge/V4l2Devices.cpp).
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

#include "common/libagent/CameraImages.hpp"

namespace common::v4l2 {

constexpr uint32_t kBlockMagic = 0x4C345753;  // "SW4L"
constexpr uint32_t kBlockVersion = 1;
constexpr int kNumCameras = common::libagent::kNumCameras;  // 0 top, 1 bottom
constexpr int kMaxDevicePath = 64;                           // bytes, with the terminating NUL
// The buffers a program may queue at once (VIDIOC_REQBUFS clamps to it).
constexpr int kMaxBuffers = 32;
constexpr int64_t kMaxImageBytes =
    int64_t(common::libagent::kMaxImageWidth) * common::libagent::kMaxImageHeight * 2;  // YUYV, 2 bytes/px

// The program's environment: the block's shared-memory name ("/simswift-v4l2-p123-t19p1").
constexpr const char* kBlockVariable = "SIMSWIFT_V4L2";

// The block of an external robot's cameras (`program: external`): named by
// its robot only ("/simswift-v4l2-t19p1"), as its clock page is, so that a
// program started by hand (`simswift attach`, or with SIMSWIFT_V4L2 set by
// hand) finds it without knowing the run's pid. One run serves a robot at a
// time (its body's lock), and a run takes a killed run's block over. A
// launched program's block keeps the run's pid in its name
// ("/simswift-v4l2-p<pid>-<tag>"): it is handed over in the environment.
inline std::string blockName(const std::string& robot_tag) { return "/simswift-v4l2-" + robot_tag; }

// The image sizes the cameras give (px): the NAO's camera modes up to the
// images block's largest (VIDIOC_S_FMT snaps a request to the largest of
// these that fits in it, as a driver adjusts; VIDIOC_ENUM_FRAMESIZES lists them).
struct FrameSize {
  int32_t width, height;
};
constexpr FrameSize kFrameSizes[] = {{160, 120}, {320, 240}, {640, 480}, {1280, 960}};
constexpr FrameSize kDefaultFrameSize = {640, 480};  // before the program's S_FMT
inline bool isFrameSize(int32_t w, int32_t h) {
  for (const FrameSize& s : kFrameSizes)
    if (s.width == w && s.height == h) return true;
  return false;
}

struct CameraChannel {
  // --- Written by the simulator (before the block's magic): ---
  char device[kMaxDevicePath];  // the path the program opens, "/dev/video-top"
  // --- Written by the simulator per frame (before it stores frames_posted, release): ---
  int64_t frame_index;   // the 30 Hz camera frame (0, 1, ...)
  int64_t sim_time_us;   // simulated time it was taken
  int32_t width, height; // px, of `image`
  std::atomic<int64_t> frames_posted;  // frames published to this camera (1, 2, ...); 0 none yet
  // --- Written by the program (the shim); the simulator reads each once per frame, checked: ---
  std::atomic<int32_t> streaming;       // 1 between VIDIOC_STREAMON and STREAMOFF (or close)
  std::atomic<int32_t> buffers_queued;  // buffers in the driver's queue (0..kMaxBuffers)
  std::atomic<int32_t> width_wanted, height_wanted;  // the format set (VIDIOC_S_FMT): a kFrameSizes entry
  std::atomic<int64_t> frames_taken;    // frames_posted of the last frame dequeued
  // --- The frame, YUYV (CameraImages.hpp's layout), rows top first, width * height * 2 bytes used. ---
  alignas(64) uint8_t image[kMaxImageBytes];
};

struct DeviceBlock {
  std::atomic<uint32_t> magic;  // kBlockMagic once set up (stored last)
  uint32_t version;             // kBlockVersion
  std::atomic<int32_t> shutdown;  // the run has ended: a waiting DQBUF returns ENODEV
  CameraChannel camera[kNumCameras];
};

// The FIFO `which` ("top", "bottom", "taken") of the block named `block`
// ("/simswift-v4l2-..."): /dev/shm/simswift-v4l2-...-top.
inline std::string fifoPath(const std::string& block, const char* which) {
  return "/dev/shm" + block + "-" + which;
}
inline const char* cameraFifo(int camera) { return camera == 0 ? "top" : "bottom"; }
constexpr const char* kTakenFifo = "taken";

}  // namespace common::v4l2
