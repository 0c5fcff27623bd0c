// The actuator side of LoLA: what a program sends back each cycle, and a
// streaming decoder for it (the socket has no framing; maps arrive split
// across reads, several per cycle, any subset of keys).
//
// Which maps make one cycle's answer (docs/lola.md, "Cycles"): every map up
// to and including the first that holds a completing key (by default
// Position or Stiffness: every public client sends both in its main map);
// maps without one (rUNSWift 2022's Sonar-only second map) are merged into
// the answer being collected, i.e. the next cycle's. Later values win per
// key. The split depends only on the byte stream, never on read timing, so
// a run stays deterministic however the bytes arrive.
//
// Bad input never crashes or aborts: a byte stream that is not msgpack, a
// value that is not a map of LoLA's keys with LoLA's lengths and finite
// numbers, or a map larger than the limit gives an error naming the map,
// its byte range and the key; the decoder then refuses more input until reset().
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include "sim/lola/Protocol.hpp"
#include "sim/lola/SensorPacket.hpp"  // JointArray

namespace simswift::lola {

struct ActuatorCommand {
  std::optional<JointArray> position;   // rad, LoLA joint order
  std::optional<JointArray> stiffness;  // 0..1 (not clamped here)
  std::optional<std::array<float, 3>> chest, lfoot, rfoot;  // RGB 0..1
  std::optional<std::array<float, 24>> leye, reye;          // 8 red, 8 green, 8 blue, 0..1
  std::optional<std::array<float, 10>> lear, rear;          // intensities 0..1
  std::optional<std::array<float, 12>> skull;               // intensities 0..1
  std::optional<std::array<bool, 2>> sonar;                 // enable left, right

  // Every key `later` holds replaces this one's.
  void mergeFrom(const ActuatorCommand& later);
  bool empty() const;
};

struct DecoderOptions {
  // Bit i set: a map holding kActuatorKeys[i] completes the cycle's answer.
  unsigned completing_keys = (1u << static_cast<int>(ActuatorKey::Position)) |
                             (1u << static_cast<int>(ActuatorKey::Stiffness));
  // Largest map accepted, bytes (all eleven keys as float64 come to about
  // 1.6 KB; LoLA's own largest, float32, is 786).
  std::size_t max_map_bytes = 4096;
  // Complete answers held before the client counts as running away (it sent
  // answers for cycles it has not been sent yet).
  std::size_t max_pending_answers = 8;
};

class ActuatorDecoder {
 public:
  explicit ActuatorDecoder(DecoderOptions options = {});
  ~ActuatorDecoder();
  ActuatorDecoder(const ActuatorDecoder&) = delete;
  ActuatorDecoder& operator=(const ActuatorDecoder&) = delete;

  // Feeds bytes as read from the socket. false: the stream is bad; error()
  // says why; nothing more is accepted until reset().
  bool feed(const void* data, std::size_t size);
  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }

  // Complete answers, oldest first.
  bool hasAnswer() const { return !answers_.empty(); }
  ActuatorCommand takeAnswer();
  // Maps decoded so far without a completing key (the answer being collected).
  const ActuatorCommand& collecting() const { return collecting_; }

  std::size_t mapsDecoded() const { return maps_; }
  std::size_t bytesFed() const { return fed_; }
  // Forgets everything (a new connection).
  void reset();

 private:
  bool fail(const std::string& message);
  DecoderOptions options_;
  struct Impl;  // the msgpack-c unpacker (kept out of this header)
  std::unique_ptr<Impl> impl_;
  ActuatorCommand collecting_;
  std::deque<ActuatorCommand> answers_;
  std::string error_;
  std::size_t maps_ = 0;
  std::size_t fed_ = 0;       // bytes fed
  std::size_t consumed_ = 0;  // bytes of complete maps
};

// One actuator map as msgpack (tests, tools, the reference client later):
// the keys the command holds, in kActuatorKeys order, float32 numbers,
// Sonar as booleans.
std::string encodeActuatorMap(const ActuatorCommand& command);

}  // namespace simswift::lola
