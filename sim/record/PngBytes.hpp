// 8-bit RGB to PNG bytes in memory (libpng), for the recording's camera
// images (foxglove.CompressedImage). Builds without cameras have no images
// to encode and no libpng: pngAvailable() is false there.
#pragma once

#include <cstdint>
#include <string>

namespace simswift::record {

bool pngAvailable();
// rgb: width * height * 3 bytes, rows top first. zlib level 1: the
// recording's cost matters more than its size. Throws std::runtime_error.
std::string encodePng(const uint8_t* rgb, int width, int height);

}  // namespace simswift::record
