#include "sim/camera/FrameDumper.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "sim/camera/Png.hpp"

namespace simswift::camera {

void makeDirectories(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw std::runtime_error(dir + ": cannot create folder" + (ec ? ": " + ec.message() : std::string()));
}

FrameDumper::FrameDumper(std::string dir, int every) : dir_(std::move(dir)), every_(every) {
  if (every_ < 1) throw std::invalid_argument("--every: must be >= 1 (got " + std::to_string(every) + ")");
  makeDirectories(dir_);
}

std::string FrameDumper::fileName(int team, int player, int camera, int64_t frame_index) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "t%dp%d_%s_%06lld.png", team, player, camera == 0 ? "top" : "bottom",
                static_cast<long long>(frame_index));
  return buf;
}

void FrameDumper::write(int team, int player, int camera, int64_t frame_index, const uint8_t* rgb, int width,
                        int height) {
  writePng(dir_ + "/" + fileName(team, player, camera, frame_index), rgb, width, height);
  ++written_;
}

void FrameDumper::dump(int team, int player, const common::libagent::CameraImages& images) {
  if (!wants(images.frame_index)) return;
  for (int c = 0; c < common::libagent::kNumCameras; ++c)
    if (images.valid[c]) write(team, player, c, images.frame_index, images.rgb[c], images.size[c].width,
                                   images.size[c].height);
}

}  // namespace simswift::camera
