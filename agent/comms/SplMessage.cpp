#include "agent/comms/SplMessage.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace agent::comms {

namespace {

// Little-endian writers/readers: the bytes are the same on any host.
struct Writer {
  std::vector<uint8_t>& out;
  void u8(uint8_t v) { out.push_back(v); }
  void i8(int8_t v) { out.push_back(static_cast<uint8_t>(v)); }
  void u16(uint16_t v) {
    out.push_back(static_cast<uint8_t>(v & 0xff));
    out.push_back(static_cast<uint8_t>(v >> 8));
  }
  void i16(int16_t v) { u16(static_cast<uint16_t>(v)); }
  void f32(float v) {
    uint32_t b;
    std::memcpy(&b, &v, 4);
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>(b >> (8 * i)));
  }
};

struct Reader {
  const uint8_t* p;
  size_t at = 0;
  uint8_t u8() { return p[at++]; }
  int8_t i8() { return static_cast<int8_t>(p[at++]); }
  uint16_t u16() {
    const uint16_t v = static_cast<uint16_t>(p[at] | (p[at + 1] << 8));
    at += 2;
    return v;
  }
  int16_t i16() { return static_cast<int16_t>(u16()); }
  float f32() {
    uint32_t b = 0;
    for (int i = 0; i < 4; ++i) b |= static_cast<uint32_t>(p[at + i]) << (8 * i);
    at += 4;
    float v;
    std::memcpy(&v, &b, 4);
    return v;
  }
};

}  // namespace

bool SplMessage::operator==(const SplMessage& o) const {
  return player == o.player && team == o.team && fallen == o.fallen && pose_x == o.pose_x && pose_y == o.pose_y &&
         pose_theta == o.pose_theta && walking_to_x == o.walking_to_x && walking_to_y == o.walking_to_y &&
         shooting_to_x == o.shooting_to_x && shooting_to_y == o.shooting_to_y && ball_age == o.ball_age &&
         ball_x == o.ball_x && ball_y == o.ball_y && ball_vel_x == o.ball_vel_x && ball_vel_y == o.ball_vel_y &&
         suggestion == o.suggestion && intention == o.intention && average_walk_speed == o.average_walk_speed &&
         max_kick_distance == o.max_kick_distance && position_confidence == o.position_confidence &&
         side_confidence == o.side_confidence && data == o.data;
}

const char* parseErrorName(ParseError e) {
  switch (e) {
    case ParseError::None: return "none";
    case ParseError::TooShort: return "too short";
    case ParseError::TooLong: return "too long";
    case ParseError::BadHeader: return "bad header";
    case ParseError::BadVersion: return "bad version";
    case ParseError::BadDataSize: return "bad numOfDataBytes";
    case ParseError::BadPlayer: return "bad player number";
    case ParseError::BadTeam: return "bad team number";
    case ParseError::BadFallen: return "bad fallen flag";
    case ParseError::NonFinite: return "non-finite value";
  }
  return "unknown";
}

std::vector<uint8_t> serialise(const SplMessage& m) {
  if (m.data.size() > kSplDataSize)
    throw std::invalid_argument("SPL message data is " + std::to_string(m.data.size()) + " bytes (at most " +
                                std::to_string(kSplDataSize) + ")");
  if (m.player < 1 || m.player > kSplMaxPlayers)
    throw std::invalid_argument("SPL message player " + std::to_string(m.player) + " (must be 1..5)");
  if (m.team < 0 || m.team > 127) throw std::invalid_argument("SPL message team " + std::to_string(m.team));
  std::vector<uint8_t> out;
  out.reserve(kSplHeadBytes + m.data.size());
  Writer w{out};
  for (char c : kSplHeader) w.u8(static_cast<uint8_t>(c));
  w.u8(kSplVersion);
  w.i8(static_cast<int8_t>(m.player));
  w.i8(static_cast<int8_t>(m.team));
  w.i8(m.fallen ? 1 : 0);
  for (float v : {m.pose_x, m.pose_y, m.pose_theta, m.walking_to_x, m.walking_to_y, m.shooting_to_x,
                  m.shooting_to_y, m.ball_age, m.ball_x, m.ball_y, m.ball_vel_x, m.ball_vel_y})
    w.f32(v);
  for (int8_t s : m.suggestion) w.i8(s);
  w.i8(m.intention);
  w.i16(m.average_walk_speed);
  w.i16(m.max_kick_distance);
  w.i8(m.position_confidence);
  w.i8(m.side_confidence);
  w.u16(static_cast<uint16_t>(m.data.size()));
  out.insert(out.end(), m.data.begin(), m.data.end());
  return out;
}

ParseResult parse(const uint8_t* bytes, size_t size) {
  ParseResult r;
  if (bytes == nullptr || size < kSplHeadBytes) {
    r.error = ParseError::TooShort;
    return r;
  }
  if (size > kSplMaxPacketBytes) {
    r.error = ParseError::TooLong;
    return r;
  }
  if (std::memcmp(bytes, kSplHeader, 4) != 0) {
    r.error = ParseError::BadHeader;
    return r;
  }
  Reader rd{bytes, 4};
  if (rd.u8() != kSplVersion) {
    r.error = ParseError::BadVersion;
    return r;
  }
  SplMessage& m = r.message;
  m.player = rd.i8();
  m.team = rd.i8();
  const int8_t fallen = rd.i8();
  float* floats[] = {&m.pose_x, &m.pose_y, &m.pose_theta, &m.walking_to_x, &m.walking_to_y, &m.shooting_to_x,
                     &m.shooting_to_y, &m.ball_age, &m.ball_x, &m.ball_y, &m.ball_vel_x, &m.ball_vel_y};
  bool finite = true;
  for (float* f : floats) {
    *f = rd.f32();
    finite = finite && std::isfinite(*f);
  }
  for (int8_t& s : m.suggestion) s = rd.i8();
  m.intention = rd.i8();
  m.average_walk_speed = rd.i16();
  m.max_kick_distance = rd.i16();
  m.position_confidence = rd.i8();
  m.side_confidence = rd.i8();
  const uint16_t n = rd.u16();
  // Checks in a fixed order, so one packet always gets the same verdict.
  if (n > kSplDataSize) r.error = ParseError::BadDataSize;
  else if (size < kSplHeadBytes + n) r.error = ParseError::TooShort;
  else if (m.player < 1 || m.player > kSplMaxPlayers) r.error = ParseError::BadPlayer;
  else if (m.team < 0) r.error = ParseError::BadTeam;
  else if (fallen != 0 && fallen != 1) r.error = ParseError::BadFallen;
  else if (!finite) r.error = ParseError::NonFinite;
  if (!r.ok()) {
    r.message = SplMessage{};
    return r;
  }
  m.fallen = fallen == 1;
  m.data.assign(bytes + kSplHeadBytes, bytes + kSplHeadBytes + n);
  return r;
}

}  // namespace agent::comms
