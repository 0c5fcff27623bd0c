// The MCAP format's facts (mcap.dev/spec, major version 0), one home for
// simswift's writer (sim/record/McapWriter) and reader (app/view/Mcap): the
// magic, the record opcodes and the CRC the spec names. Little-endian
// integers; a record = uint8 opcode + uint64 content length + content.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace common::mcap {

// The 8 bytes that open and close a file.
constexpr char kMagic[8] = {'\x89', 'M', 'C', 'A', 'P', '0', '\r', '\n'};

enum Op : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,  // the highest opcode the spec defines; 0x80+ are private records
};

// CRC-32 (ISO-HDLC, zlib's: the one the spec names), continued from `crc`
// (0 to start): crc32(0, "123456789", 9) == 0xCBF43926.
inline std::uint32_t crc32(std::uint32_t crc, const void* data, std::size_t size) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  const auto* p = static_cast<const std::uint8_t*>(data);
  crc = ~crc;
  for (std::size_t i = 0; i < size; ++i) crc = table[(crc ^ p[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

}  // namespace common::mcap
