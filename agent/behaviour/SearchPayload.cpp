#include "agent/behaviour/SearchPayload.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace agent::behaviour {
namespace {

constexpr uint8_t kVersion = 1;
constexpr size_t kHeader = 11;

void put16(std::vector<uint8_t>& b, uint16_t v) {
  b.push_back(static_cast<uint8_t>(v & 0xff));
  b.push_back(static_cast<uint8_t>(v >> 8));
}
uint16_t get16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }
int16_t clampMm(double v) {
  return static_cast<int16_t>(std::lround(std::clamp(v, -32767.0, 32767.0)));
}
uint16_t checksum(const uint8_t* p, size_t n) {
  uint32_t s = 0;
  for (size_t i = 0; i < n; ++i) s += p[i];
  return static_cast<uint16_t>(s & 0xffff);
}
std::optional<SearchPayload> reject(std::string* why, const char* reason) {
  if (why) *why = reason;
  return std::nullopt;
}

}  // namespace

std::vector<uint8_t> SearchPayload::toBytes() const {
  const int j = columns * rows;
  if (columns < 1 || rows < 1 || columns > 255 || rows > 255 || j > kMaxSegments)
    throw std::invalid_argument("SearchPayload: grid does not fit the packet");
  if (static_cast<int>(probabilities.size()) != j)
    throw std::invalid_argument("SearchPayload: probabilities do not match the grid");
  if (segment < -1 || segment >= j) throw std::invalid_argument("SearchPayload: bad segment");
  std::vector<uint8_t> b;
  b.reserve(kHeader + 2 * j + 2);
  b.push_back('S');
  b.push_back('B');
  b.push_back(kVersion);
  b.push_back(static_cast<uint8_t>(std::clamp(player, 0, 255)));
  b.push_back(static_cast<uint8_t>(columns));
  b.push_back(static_cast<uint8_t>(rows));
  b.push_back(segment < 0 ? uint8_t{0xff} : static_cast<uint8_t>(segment));
  put16(b, static_cast<uint16_t>(clampMm(point.x)));
  put16(b, static_cast<uint16_t>(clampMm(point.y)));
  for (double p : probabilities)
    put16(b, static_cast<uint16_t>(std::lround(std::clamp(p, 0.0, 1.0) * 65535.0)));
  put16(b, checksum(b.data(), b.size()));
  return b;
}

std::optional<SearchPayload> SearchPayload::fromBytes(const uint8_t* d, size_t n,
                                                      std::string* why) {
  if (d == nullptr || n < kHeader + 2) return reject(why, "too short");
  if (n > kMaxBytes) return reject(why, "longer than the free data area");
  if (d[0] != 'S' || d[1] != 'B') return reject(why, "bad magic");
  if (d[2] != kVersion) return reject(why, "unknown version");
  SearchPayload s;
  s.player = d[3];
  s.columns = d[4];
  s.rows = d[5];
  const int j = s.columns * s.rows;
  if (j < 1 || j > kMaxSegments) return reject(why, "bad grid size");
  if (n != kHeader + 2 * static_cast<size_t>(j) + 2) return reject(why, "length does not match the grid");
  if (checksum(d, n - 2) != get16(d + n - 2)) return reject(why, "bad checksum");
  s.segment = d[6] == 0xff ? -1 : d[6];
  if (s.segment < -1 || s.segment >= j) return reject(why, "segment out of range");
  s.point = {static_cast<double>(static_cast<int16_t>(get16(d + 7))),
             static_cast<double>(static_cast<int16_t>(get16(d + 9)))};
  s.probabilities.resize(j);
  double sum = 0;
  for (int k = 0; k < j; ++k) {
    s.probabilities[k] = get16(d + kHeader + 2 * k) / 65535.0;
    sum += s.probabilities[k];
  }
  if (!(sum > 0)) return reject(why, "all-zero distribution");
  for (double& p : s.probabilities) p /= sum;
  return s;
}

}  // namespace agent::behaviour
