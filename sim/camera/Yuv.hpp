// RGB <-> YUV422 (YUYV) conversion as the NAO camera delivers frames.
//
// Colour space: ITU-R BT.601 full range (the JPEG/JFIF convention): Y, U, V
// all span 0..255 and 128 means no chroma.
//   Y = 0.299 R + 0.587 G + 0.114 B
//   U = 128 + (B - Y) * 0.564      (= -0.168736 R - 0.331264 G + 0.5 B)
//   V = 128 + (R - Y) * 0.713      (=  0.5 R - 0.418688 G - 0.081312 B)
//   R = Y + 1.402 (V-128);  G = Y - 0.344136 (U-128) - 0.714136 (V-128);
//   B = Y + 1.772 (U-128)
// Packing: for each horizontal pixel pair (2i, 2i+1): Y0 U Y1 V, where U and V
// are computed from the pair's average colour. Integer arithmetic with 16
// fractional bits, rounded to nearest, so results are exact and portable.
// Width must be even.
#pragma once

#include <cstdint>

namespace simswift::camera {

// rgb: width*height*3 bytes; yuyv: width*height*2 bytes. Rows top first.
void rgbToYuyv(const uint8_t* rgb, int width, int height, uint8_t* yuyv);
void yuyvToRgb(const uint8_t* yuyv, int width, int height, uint8_t* rgb);

}  // namespace simswift::camera
