// Minimal PNG I/O (libpng) for frame dumps and tests: 8-bit RGB, rows top first.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace simswift::camera {

// Throws std::runtime_error naming the file on failure.
void writePng(const std::string& path, const uint8_t* rgb, int width, int height);
// Reads an 8-bit RGB or RGBA PNG into RGB.
std::vector<uint8_t> readPng(const std::string& path, int* width, int* height);

}  // namespace simswift::camera
