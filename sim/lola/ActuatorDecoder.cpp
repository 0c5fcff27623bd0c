#include "sim/lola/ActuatorDecoder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <sstream>

#include <msgpack.hpp>

namespace simswift::lola {

void ActuatorCommand::mergeFrom(const ActuatorCommand& later) {
  if (later.position) position = later.position;
  if (later.stiffness) stiffness = later.stiffness;
  if (later.chest) chest = later.chest;
  if (later.lfoot) lfoot = later.lfoot;
  if (later.rfoot) rfoot = later.rfoot;
  if (later.leye) leye = later.leye;
  if (later.reye) reye = later.reye;
  if (later.lear) lear = later.lear;
  if (later.rear) rear = later.rear;
  if (later.skull) skull = later.skull;
  if (later.sonar) sonar = later.sonar;
}

bool ActuatorCommand::empty() const {
  return !position && !stiffness && !chest && !lfoot && !rfoot && !leye && !reye && !lear && !rear && !skull &&
         !sonar;
}

namespace {

// Per-object limits handed to msgpack-c: it refuses a header announcing more
// (a garbage array32 header of 4 G elements is an error, never an allocation).
// The byte limit (DecoderOptions::max_map_bytes) bounds everything else.
msgpack::unpack_limit objectLimits() {
  return msgpack::unpack_limit(/*array*/ 64, /*map*/ 32, /*str*/ 64, /*bin*/ 64, /*ext*/ 0, /*depth*/ 4);
}

// Bytes handed to msgpack-c per step: the byte limit is checked between steps.
constexpr std::size_t kFeedChunk = 1024;

std::string typeName(const msgpack::object& o) {
  switch (o.type) {
    case msgpack::type::NIL: return "nil";
    case msgpack::type::BOOLEAN: return "a boolean";
    case msgpack::type::POSITIVE_INTEGER:
    case msgpack::type::NEGATIVE_INTEGER: return "an integer";
    case msgpack::type::FLOAT32:
    case msgpack::type::FLOAT64: return "a float";
    case msgpack::type::STR: return "a string";
    case msgpack::type::BIN: return "binary";
    case msgpack::type::ARRAY: return "an array";
    case msgpack::type::MAP: return "a map";
    case msgpack::type::EXT: return "an ext";
  }
  return "unknown";
}

// One number of an actuator array: any msgpack number (float32 as LoLA's
// clients send, float64 and integers as generic packers do). Booleans only
// where `allow_bool` (Sonar: HULKs and rUNSWift send booleans there).
bool number(const msgpack::object& o, bool allow_bool, double& out) {
  switch (o.type) {
    case msgpack::type::FLOAT32:
    case msgpack::type::FLOAT64:
      out = o.via.f64;
      return std::isfinite(static_cast<float>(out));  // a float64 beyond float32's range too
    case msgpack::type::POSITIVE_INTEGER: out = static_cast<double>(o.via.u64); return true;
    case msgpack::type::NEGATIVE_INTEGER: out = static_cast<double>(o.via.i64); return true;
    case msgpack::type::BOOLEAN:
      out = o.via.boolean ? 1.0 : 0.0;
      return allow_bool;
    default: return false;
  }
}

// Checks one map and turns it into a command; "" or the reason it is refused.
std::string toCommand(const msgpack::object& o, ActuatorCommand& c) {
  if (o.type != msgpack::type::MAP) return "expected a map, got " + typeName(o);
  unsigned seen = 0;
  for (std::uint32_t e = 0; e < o.via.map.size; ++e) {
    const msgpack::object& k = o.via.map.ptr[e].key;
    const msgpack::object& v = o.via.map.ptr[e].val;
    if (k.type != msgpack::type::STR) return "a key is " + typeName(k) + ", LoLA's keys are strings";
    const std::string_view name(k.via.str.ptr, k.via.str.size);
    const int key = actuatorKeyIndex(name);
    const std::string quoted = "key \"" + std::string(name.substr(0, 32)) + "\"";
    if (key < 0) return quoted + ": not a LoLA actuator key";
    if (seen & (1u << key)) return quoted + ": given twice in one map";
    seen |= 1u << key;
    const int length = kActuatorKeys[key].length;
    if (v.type != msgpack::type::ARRAY) return quoted + ": expected an array, got " + typeName(v);
    if (static_cast<int>(v.via.array.size) != length)
      return quoted + ": " + std::to_string(v.via.array.size) + " values, LoLA takes " + std::to_string(length);
    const bool is_sonar = key == static_cast<int>(ActuatorKey::Sonar);
    double values[32];
    for (int i = 0; i < length; ++i)
      if (!number(v.via.array.ptr[i], is_sonar, values[i]))
        return quoted + "[" + std::to_string(i) + "]: " + typeName(v.via.array.ptr[i]) +
               (is_sonar ? ", expected a boolean or a number" : ", expected a finite number");
    auto fill = [&](auto& slot) {
      slot.emplace();
      for (int i = 0; i < length; ++i) (*slot)[i] = static_cast<float>(values[i]);
    };
    switch (static_cast<ActuatorKey>(key)) {
      case ActuatorKey::Position: fill(c.position); break;
      case ActuatorKey::Stiffness: fill(c.stiffness); break;
      case ActuatorKey::Chest: fill(c.chest); break;
      case ActuatorKey::LEye: fill(c.leye); break;
      case ActuatorKey::REye: fill(c.reye); break;
      case ActuatorKey::LEar: fill(c.lear); break;
      case ActuatorKey::REar: fill(c.rear); break;
      case ActuatorKey::LFoot: fill(c.lfoot); break;
      case ActuatorKey::RFoot: fill(c.rfoot); break;
      case ActuatorKey::Skull: fill(c.skull); break;
      case ActuatorKey::Sonar:
        c.sonar.emplace();
        for (int i = 0; i < 2; ++i) (*c.sonar)[i] = values[i] != 0.0;
        break;
    }
  }
  return "";
}

unsigned keyMask(const ActuatorCommand& c) {
  unsigned m = 0;
  auto bit = [&](bool has, ActuatorKey k) {
    if (has) m |= 1u << static_cast<int>(k);
  };
  bit(c.position.has_value(), ActuatorKey::Position);
  bit(c.stiffness.has_value(), ActuatorKey::Stiffness);
  bit(c.chest.has_value(), ActuatorKey::Chest);
  bit(c.leye.has_value(), ActuatorKey::LEye);
  bit(c.reye.has_value(), ActuatorKey::REye);
  bit(c.lear.has_value(), ActuatorKey::LEar);
  bit(c.rear.has_value(), ActuatorKey::REar);
  bit(c.lfoot.has_value(), ActuatorKey::LFoot);
  bit(c.rfoot.has_value(), ActuatorKey::RFoot);
  bit(c.skull.has_value(), ActuatorKey::Skull);
  bit(c.sonar.has_value(), ActuatorKey::Sonar);
  return m;
}

}  // namespace

// Decoded objects never point into the unpacker's buffer (they are copied
// into its zone): a map is converted before the next feed anyway.
bool neverReference(msgpack::type::object_type, std::size_t, void*) { return false; }

struct ActuatorDecoder::Impl {
  msgpack::unpacker unpacker{&neverReference, nullptr,
                             MSGPACK_UNPACKER_INIT_BUFFER_SIZE, objectLimits()};
};

ActuatorDecoder::ActuatorDecoder(DecoderOptions options) : options_(options), impl_(std::make_unique<Impl>()) {}
ActuatorDecoder::~ActuatorDecoder() = default;

void ActuatorDecoder::reset() {
  impl_ = std::make_unique<Impl>();
  collecting_ = {};
  answers_.clear();
  error_.clear();
  maps_ = fed_ = consumed_ = 0;
}

bool ActuatorDecoder::fail(const std::string& message) {
  std::ostringstream s;
  s << "LoLA actuator stream, map " << (maps_ + 1) << " (from byte " << consumed_ << "): " << message;
  error_ = s.str();
  return false;
}

ActuatorCommand ActuatorDecoder::takeAnswer() {
  ActuatorCommand c = std::move(answers_.front());
  answers_.pop_front();
  return c;
}

bool ActuatorDecoder::feed(const void* data, std::size_t size) {
  if (failed()) return false;
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const std::size_t n = std::min(size, kFeedChunk);
    try {
      impl_->unpacker.reserve_buffer(n);
      std::memcpy(impl_->unpacker.buffer(), bytes, n);
      impl_->unpacker.buffer_consumed(n);
      fed_ += n;
      bytes += n;
      size -= n;
      msgpack::object_handle handle;
      while (impl_->unpacker.next(handle)) {
        const std::size_t end = fed_ - impl_->unpacker.nonparsed_size();
        if (end - consumed_ > options_.max_map_bytes)
          return fail(std::to_string(end - consumed_) + " bytes, more than the limit of " +
                      std::to_string(options_.max_map_bytes));
        ActuatorCommand map;
        const std::string why = toCommand(handle.get(), map);
        if (!why.empty()) return fail(why);
        collecting_.mergeFrom(map);
        ++maps_;
        consumed_ = end;
        if (keyMask(map) & options_.completing_keys) {
          if (answers_.size() >= options_.max_pending_answers)
            return fail("more than " + std::to_string(options_.max_pending_answers) +
                        " answers ahead of the cycles sent");
          answers_.push_back(std::move(collecting_));
          collecting_ = {};
        }
      }
    } catch (const std::exception& e) {
      // msgpack-c: parse_error (a byte no msgpack value starts with),
      // *_size_overflow (a header beyond objectLimits), depth_size_overflow.
      return fail(std::string("not a msgpack map of LoLA's (") + e.what() + ")");
    }
    if (fed_ - consumed_ > options_.max_map_bytes)
      return fail("no complete map within " + std::to_string(options_.max_map_bytes) + " bytes");
  }
  return true;
}

std::string encodeActuatorMap(const ActuatorCommand& c) {
  msgpack::sbuffer buffer;
  msgpack::packer<msgpack::sbuffer> pk(buffer);
  const unsigned mask = keyMask(c);
  pk.pack_map(static_cast<std::uint32_t>(__builtin_popcount(mask)));
  auto floats = [&](ActuatorKey key, const float* values, int n) {
    const std::string_view name = kActuatorKeys[static_cast<int>(key)].name;
    pk.pack_str(static_cast<std::uint32_t>(name.size()));
    pk.pack_str_body(name.data(), static_cast<std::uint32_t>(name.size()));
    pk.pack_array(static_cast<std::uint32_t>(n));
    char bytes[5];
    for (int i = 0; i < n; ++i) {
      writeFloat32(bytes, values[i]);  // float32 always, as LoLA's clients send
      buffer.write(bytes, 5);
    }
  };
  if (c.position) floats(ActuatorKey::Position, c.position->data(), kNumJoints);
  if (c.stiffness) floats(ActuatorKey::Stiffness, c.stiffness->data(), kNumJoints);
  if (c.chest) floats(ActuatorKey::Chest, c.chest->data(), 3);
  if (c.leye) floats(ActuatorKey::LEye, c.leye->data(), 24);
  if (c.reye) floats(ActuatorKey::REye, c.reye->data(), 24);
  if (c.lear) floats(ActuatorKey::LEar, c.lear->data(), 10);
  if (c.rear) floats(ActuatorKey::REar, c.rear->data(), 10);
  if (c.lfoot) floats(ActuatorKey::LFoot, c.lfoot->data(), 3);
  if (c.rfoot) floats(ActuatorKey::RFoot, c.rfoot->data(), 3);
  if (c.skull) floats(ActuatorKey::Skull, c.skull->data(), 12);
  if (c.sonar) {
    pk.pack_str(5);
    pk.pack_str_body("Sonar", 5);
    pk.pack_array(2);
    for (bool b : *c.sonar) pk.pack(b);
  }
  return std::string(buffer.data(), buffer.size());
}

}  // namespace simswift::lola
