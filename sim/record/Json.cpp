#include "sim/record/Json.hpp"

namespace simswift::record {

Json& Json::base64(const uint8_t* data, size_t size) {
  static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  sep();
  s_ += '"';
  size_t i = 0;
  for (; i + 3 <= size; i += 3) {
    const uint32_t v = (uint32_t{data[i]} << 16) | (uint32_t{data[i + 1]} << 8) | data[i + 2];
    s_ += abc[v >> 18];
    s_ += abc[(v >> 12) & 63];
    s_ += abc[(v >> 6) & 63];
    s_ += abc[v & 63];
  }
  if (size - i == 1) {
    const uint32_t v = uint32_t{data[i]} << 16;
    s_ += abc[v >> 18];
    s_ += abc[(v >> 12) & 63];
    s_ += "==";
  } else if (size - i == 2) {
    const uint32_t v = (uint32_t{data[i]} << 16) | (uint32_t{data[i + 1]} << 8);
    s_ += abc[v >> 18];
    s_ += abc[(v >> 12) & 63];
    s_ += abc[(v >> 6) & 63];
    s_ += '=';
  }
  s_ += '"';
  return *this;
}

}  // namespace simswift::record
