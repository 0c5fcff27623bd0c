#include "sim/record/PngBytes.hpp"

#include <stdexcept>

#ifdef SIMSWIFT_HAVE_CAMERAS
#include <png.h>
#endif

namespace simswift::record {

#ifdef SIMSWIFT_HAVE_CAMERAS

namespace {
void append(png_structp png, png_bytep data, png_size_t size) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), size);
}
void noFlush(png_structp) {}
}  // namespace

bool pngAvailable() { return true; }

std::string encodePng(const uint8_t* rgb, int width, int height) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("recording: cannot start a PNG encoder");
  }
  if (setjmp(png_jmpbuf(png))) {  // libpng's error path
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("recording: PNG encoding failed");
  }
  png_set_write_fn(png, &out, append, noFlush);
  png_set_compression_level(png, 1);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(rgb + static_cast<size_t>(y) * width * 3));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

#else

bool pngAvailable() { return false; }
std::string encodePng(const uint8_t*, int, int) { throw std::runtime_error("recording: built without cameras"); }

#endif

}  // namespace simswift::record
