// Writes the robots' camera frames as PNGs for `simswift run ... --dump-frames
// DIR --every N`: DIR/t<team>p<player>_<top|bottom>_<frame:06d>.png for every
// N-th camera frame (frame index divisible by N, so frame 0 is always kept).
//
// Runner hook: construct once with (DIR, N); after RobotCameras::fillImages
// for a robot, call dump(team, player, images) (it checks wants() itself).
// The folder is created if missing.
#pragma once

#include <cstdint>
#include <string>

#include "common/libagent/CameraImages.hpp"

namespace simswift::camera {

class FrameDumper {
 public:
  FrameDumper(std::string dir, int every);

  bool wants(int64_t frame_index) const { return frame_index % every_ == 0; }
  // Both cameras' RGB images of `images` (those marked valid), if wanted.
  void dump(int team, int player, const common::libagent::CameraImages& images);
  // One image; always written.
  void write(int team, int player, int camera, int64_t frame_index, const uint8_t* rgb, int width,
             int height);
  static std::string fileName(int team, int player, int camera, int64_t frame_index);

  const std::string& dir() const { return dir_; }
  int64_t written() const { return written_; }

 private:
  std::string dir_;
  int every_;
  int64_t written_ = 0;
};

// Creates a folder and its parents; throws std::runtime_error naming it.
void makeDirectories(const std::string& dir);

}  // namespace simswift::camera
