// Builds MCAP files byte by byte for the viewer's tests (https://mcap.dev/spec):
// little-endian fields, the records the tests need.
#pragma once

#include <cstdint>
#include <string>

namespace simswift::view::testing {

// Little-endian writers and the records the tests need.
struct Bytes {
  std::string b;
  Bytes& u8(unsigned v) { b += static_cast<char>(v); return *this; }
  Bytes& u16(unsigned v) { return u8(v & 0xFF).u8(v >> 8); }
  Bytes& u32(std::uint32_t v) { for (int i = 0; i < 4; ++i) u8((v >> (8 * i)) & 0xFF); return *this; }
  Bytes& u64(std::uint64_t v) { for (int i = 0; i < 8; ++i) u8((v >> (8 * i)) & 0xFF); return *this; }
  Bytes& str(const std::string& s) { u32(static_cast<std::uint32_t>(s.size())); b += s; return *this; }
  Bytes& raw(const std::string& s) { b += s; return *this; }
};
inline const std::string kMagic("\x89MCAP0\r\n", 8);

inline std::string record(unsigned op, const std::string& content) {
  return Bytes().u8(op).u64(content.size()).raw(content).b;
}
inline std::string header() { return record(0x01, Bytes().str("").str("test").b); }
inline std::string schema(unsigned id) { return record(0x03, Bytes().u16(id).str("s.Thing").str("jsonschema").str("{}").b); }
inline std::string channel(unsigned id, unsigned schema_id, const std::string& topic) {
  return record(0x04, Bytes().u16(id).u16(schema_id).str(topic).str("json").u32(0).b);
}
inline std::string message(unsigned channel_id, std::uint64_t t, const std::string& data) {
  return record(0x05, Bytes().u16(channel_id).u32(0).u64(t).u64(t).raw(data).b);
}
inline std::string metadata() {
  Bytes kv;
  kv.str("seed").str("7").str("scenario").str("walk_one.yaml");
  return record(0x0C, Bytes().str("simswift").u32(static_cast<std::uint32_t>(kv.b.size())).raw(kv.b).b);
}
inline std::uint32_t crc32(const std::string& s) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : s) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
  }
  return c ^ 0xFFFFFFFFu;
}
inline std::string chunk(const std::string& records, const std::string& compression = "", bool good_crc = true) {
  return record(0x06, Bytes().u64(0).u64(0).u64(records.size()).u32(good_crc ? crc32(records) : 1).str(compression)
                          .u64(records.size()).raw(records).b);
}
inline std::string tail() { return record(0x0F, Bytes().u32(0).b) + record(0x02, Bytes().u64(0).u64(0).u32(0).b) + kMagic; }

}  // namespace simswift::view::testing
