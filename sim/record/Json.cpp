#include "sim/record/Json.hpp"

namespace simswift::record {

void Json::quoted(std::string_view v) {
  s_ += '"';
  size_t plain = 0;  // start of the run of characters that need no escape
  for (size_t i = 0; i < v.size(); ++i) {
    const char c = v[i];
    const auto u = static_cast<unsigned char>(c);
    if (c != '"' && c != '\\' && u >= 0x20) continue;  // UTF-8 passes through
    s_.append(v.data() + plain, i - plain);
    plain = i + 1;
    if (u >= 0x20) {
      s_ += '\\';
      s_ += c;
    } else {
      static const char* hex = "0123456789abcdef";
      s_ += "\\u00";
      s_ += hex[u >> 4];
      s_ += hex[u & 15];
    }
  }
  s_.append(v.data() + plain, v.size() - plain);
  s_ += '"';
}

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
