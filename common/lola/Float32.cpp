#include "common/lola/Float32.hpp"

#include <cstdint>
#include <cstring>

namespace common::lola {

void writeFloat32(char* out, float value) {
  std::uint32_t bits;
  std::memcpy(&bits, &value, 4);
  out[0] = static_cast<char>(0xca);
  out[1] = static_cast<char>(bits >> 24);
  out[2] = static_cast<char>(bits >> 16);
  out[3] = static_cast<char>(bits >> 8);
  out[4] = static_cast<char>(bits);
}

}  // namespace common::lola
