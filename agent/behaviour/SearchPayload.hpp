// SearchPayload: what one robot tells its teammates about its ball search,
// carried in the SPL standard message's free data area (at most 474 bytes):
// its local ball distribution (thesis 4.2.1.2) and the segment / point it is
// heading to (thesis 4.2.2.2).
//
// Wire format (little-endian, 13 + 2 J bytes):
//   0  'S' 'B'           magic
//   2  uint8  version    (1)
//   3  uint8  player     (1..255)
//   4  uint8  columns, uint8 rows   (grid, J = columns x rows, 1..230)
//   6  uint8  segment    (0-based chosen segment, 255 = none)
//   7  int16  point x, int16 point y   (mm, field frame)
//  11  uint16 P_j x 65535, J of them
//  ... uint16 checksum (sum of all preceding bytes, mod 65536)
// Decoding rejects (returns empty with a reason) anything malformed: short or
// long buffer, wrong magic/version, empty or oversized grid, segment out of
// range, bad checksum, all-zero distribution.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "agent/behaviour/Geometry.hpp"

namespace agent::behaviour {

struct SearchPayload {
  static constexpr size_t kMaxBytes = 474;  // SPL standard message free data area
  static constexpr int kMaxSegments = 230;  // (474 - 13) / 2

  int player = 0;
  int columns = 3, rows = 3;
  std::vector<double> probabilities;  // local distribution, J values summing to 1
  int segment = -1;                   // chosen segment (0-based), -1 = none
  Point2 point;                       // chosen search point, field mm

  std::vector<uint8_t> toBytes() const;  // throws std::invalid_argument if it cannot fit
  static std::optional<SearchPayload> fromBytes(const uint8_t* data, size_t size,
                                                std::string* why = nullptr);
  static std::optional<SearchPayload> fromBytes(const std::vector<uint8_t>& b,
                                                std::string* why = nullptr) {
    return fromBytes(b.data(), b.size(), why);
  }
};

}  // namespace agent::behaviour
