#include "sim/lola/SensorPacket.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <msgpack.hpp>

namespace simswift::lola {

namespace {

// A fixed-capacity stream for msgpack::packer: the packet is written into a
// PacketBytes; more than 896 bytes is a bug in this file, not bad input.
struct FixedBuffer {
  PacketBytes* out;
  std::size_t size = 0;
  void write(const char* data, std::size_t n) {
    if (size + n > out->size()) throw std::logic_error("lola: sensor packet larger than 896 bytes");
    std::memcpy(out->data() + size, data, n);
    size += n;
  }
};

template <std::size_t N>
void packFloats(msgpack::packer<FixedBuffer>& pk, FixedBuffer& out, const std::array<float, N>& values) {
  pk.pack_array(static_cast<std::uint32_t>(N));  // N < 16: fixarray; N = 25: array16 (0xdc 00 19)
  char bytes[5];
  for (float v : values) {
    writeFloat32(bytes, v);  // float32 whatever the value (SensorPacket.hpp)
    out.write(bytes, 5);
  }
}

void packKey(msgpack::packer<FixedBuffer>& pk, SensorKey key) {
  const std::string_view name = kSensorKeys[static_cast<int>(key)].name;
  pk.pack_str(static_cast<std::uint32_t>(name.size()));  // fixstr (< 32 bytes)
  pk.pack_str_body(name.data(), static_cast<std::uint32_t>(name.size()));
}

// LoLA's length exactly: cut, or padded with '0' (the ids are digits and
// capitals; a padded version "6" becomes "60000", which the clients read
// by its first digit).
std::string fitted(const std::string& s, std::size_t length) {
  std::string out = s.substr(0, length);
  out.resize(length, '0');
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '0';
  return out;
}

}  // namespace

std::string checkRobotConfig(const std::array<std::string, 4>& config) {
  static const char* const kWhat[4] = {"body id", "body version", "head id", "head version"};
  for (int i = 0; i < 4; ++i) {
    if (config[i].size() != kRobotConfigLengths[i])
      return std::string("RobotConfig ") + kWhat[i] + " \"" + config[i] + "\": LoLA gives " +
             std::to_string(kRobotConfigLengths[i]) + " characters (got " + std::to_string(config[i].size()) + ")";
    for (char c : config[i])
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e)
        return std::string("RobotConfig ") + kWhat[i] + ": only printable ASCII";
  }
  if (config[BodyVersion][0] < '0' || config[BodyVersion][0] > '9' || config[HeadVersion][0] < '0' ||
      config[HeadVersion][0] > '9')
    return "RobotConfig versions must start with a digit (HULKs reads the major version from it)";
  return "";
}

PacketBytes encodeSensorPacket(const SensorPacket& p) {
  PacketBytes bytes{};
  FixedBuffer buffer{&bytes};
  msgpack::packer<FixedBuffer> pk(buffer);
  pk.pack_map(kNumSensorKeys);  // fixmap, 13 entries
  for (int k = 0; k < kNumSensorKeys; ++k) {
    const auto key = static_cast<SensorKey>(k);
    packKey(pk, key);
    switch (key) {
      case SensorKey::Stiffness: packFloats(pk, buffer, p.stiffness); break;
      case SensorKey::Position: packFloats(pk, buffer, p.position); break;
      case SensorKey::Temperature: packFloats(pk, buffer, p.temperature); break;
      case SensorKey::Current: packFloats(pk, buffer, p.current); break;
      case SensorKey::Battery: packFloats(pk, buffer, p.battery); break;
      case SensorKey::Accelerometer: packFloats(pk, buffer, p.accelerometer); break;
      case SensorKey::Gyroscope: packFloats(pk, buffer, p.gyroscope); break;
      case SensorKey::Angles: packFloats(pk, buffer, p.angles); break;
      case SensorKey::Sonar: packFloats(pk, buffer, p.sonar); break;
      case SensorKey::FSR: packFloats(pk, buffer, p.fsr); break;
      case SensorKey::Status:
        pk.pack_array(kNumJoints);
        // Positive fixints (one byte each): LoLA's 0..3, clamped so the
        // layout cannot change.
        for (std::uint8_t s : p.status) pk.pack_uint8(std::min<std::uint8_t>(s, 3));
        break;
      case SensorKey::Touch: packFloats(pk, buffer, p.touch); break;
      case SensorKey::RobotConfig:
        pk.pack_array(4);
        for (int i = 0; i < 4; ++i) {
          const std::string s = fitted(p.robot_config[i], kRobotConfigLengths[i]);
          pk.pack_str(static_cast<std::uint32_t>(s.size()));
          pk.pack_str_body(s.data(), static_cast<std::uint32_t>(s.size()));
        }
        break;
    }
  }
  if (buffer.size != kSensorPacketBytes) throw std::logic_error("lola: sensor packet is not 896 bytes");
  return bytes;
}

namespace {

// Strict reader for decodeSensorPacket: walks the bytes in the exact
// layout the encoder writes.
struct Reader {
  const std::uint8_t* p;
  const std::uint8_t* end;
  std::string error;
  std::size_t offset(const std::uint8_t* start) const { return static_cast<std::size_t>(p - start); }
  bool need(std::size_t n) {
    if (static_cast<std::size_t>(end - p) < n) {
      error = "truncated";
      return false;
    }
    return true;
  }
  bool arrayHeader(int expected) {
    int n;
    if (!need(1)) return false;
    if ((*p & 0xf0) == 0x90) {
      n = *p & 0x0f;
      p += 1;
    } else if (*p == 0xdc) {
      if (!need(3)) return false;
      n = (p[1] << 8) | p[2];
      p += 3;
    } else {
      error = "expected an array";
      return false;
    }
    if (n != expected) {
      error = "array of " + std::to_string(n) + ", expected " + std::to_string(expected);
      return false;
    }
    return true;
  }
  bool fixstr(std::string& out) {
    if (!need(1) || (*p & 0xe0) != 0xa0) {
      if (error.empty()) error = "expected a fixstr";
      return false;
    }
    const std::size_t n = *p & 0x1f;
    ++p;
    if (!need(n)) return false;
    out.assign(reinterpret_cast<const char*>(p), n);
    p += n;
    return true;
  }
  bool float32(float& out) {
    if (!need(5) || *p != 0xca) {
      if (error.empty()) error = "expected a float32";
      return false;
    }
    const std::uint32_t bits = (std::uint32_t(p[1]) << 24) | (std::uint32_t(p[2]) << 16) |
                               (std::uint32_t(p[3]) << 8) | std::uint32_t(p[4]);
    std::memcpy(&out, &bits, 4);
    p += 5;
    return true;
  }
  template <std::size_t N>
  bool floats(std::array<float, N>& out) {
    if (!arrayHeader(static_cast<int>(N))) return false;
    for (float& v : out)
      if (!float32(v)) return false;
    return true;
  }
};

}  // namespace

std::optional<SensorPacket> decodeSensorPacket(const std::uint8_t* data, std::size_t size, std::string* error) {
  Reader r{data, data + size, {}};
  SensorPacket p;
  auto fail = [&](const std::string& what) -> std::optional<SensorPacket> {
    if (error) *error = "LoLA sensor packet, byte " + std::to_string(r.offset(data)) + ": " + what;
    return std::nullopt;
  };
  if (size != kSensorPacketBytes) return fail("size " + std::to_string(size) + ", LoLA sends 896");
  if (data[0] != (0x80 | kNumSensorKeys)) return fail("expected a fixmap of 13 keys");
  r.p += 1;
  for (int k = 0; k < kNumSensorKeys; ++k) {
    std::string name;
    if (!r.fixstr(name)) return fail(r.error);
    if (name != kSensorKeys[k].name)
      return fail("key " + std::to_string(k) + " is \"" + name + "\", expected \"" + std::string(kSensorKeys[k].name) + "\"");
    bool ok = true;
    switch (static_cast<SensorKey>(k)) {
      case SensorKey::Stiffness: ok = r.floats(p.stiffness); break;
      case SensorKey::Position: ok = r.floats(p.position); break;
      case SensorKey::Temperature: ok = r.floats(p.temperature); break;
      case SensorKey::Current: ok = r.floats(p.current); break;
      case SensorKey::Battery: ok = r.floats(p.battery); break;
      case SensorKey::Accelerometer: ok = r.floats(p.accelerometer); break;
      case SensorKey::Gyroscope: ok = r.floats(p.gyroscope); break;
      case SensorKey::Angles: ok = r.floats(p.angles); break;
      case SensorKey::Sonar: ok = r.floats(p.sonar); break;
      case SensorKey::FSR: ok = r.floats(p.fsr); break;
      case SensorKey::Status:
        ok = r.arrayHeader(kNumJoints);
        for (int i = 0; ok && i < kNumJoints; ++i) {
          if (!r.need(1) || (*r.p & 0x80)) {
            r.error = "Status: expected a positive fixint";
            ok = false;
          } else {
            p.status[i] = *r.p++;
          }
        }
        break;
      case SensorKey::Touch: ok = r.floats(p.touch); break;
      case SensorKey::RobotConfig:
        ok = r.arrayHeader(4);
        for (int i = 0; ok && i < 4; ++i) ok = r.fixstr(p.robot_config[i]);
        break;
    }
    if (!ok) return fail(std::string(kSensorKeys[k].name) + ": " + r.error);
  }
  if (r.p != r.end) return fail("trailing bytes");
  return p;
}

}  // namespace simswift::lola
