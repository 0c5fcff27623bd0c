// A small JSON text builder for the recording's messages: appends to one
// string, no allocation per value beyond the string's growth. Numbers are
// written as the shortest text that reads back to the same float (single
// precision: 1e-7 relative, ~0.1 um at 1 m), deterministic on every
// platform (std::to_chars); NaN and infinities, which JSON has no word for,
// as null.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "common/json/JsonString.hpp"

namespace simswift::record {

class Json {
 public:
  std::string& text() { return s_; }
  void clear() { s_.clear(); first_ = true; }

  Json& open() { sep(); s_ += '{'; first_ = true; return *this; }
  Json& close() { s_ += '}'; first_ = false; return *this; }
  Json& openArray() { sep(); s_ += '['; first_ = true; return *this; }
  Json& closeArray() { s_ += ']'; first_ = false; return *this; }
  // A key; the value follows.
  Json& key(std::string_view k) {
    sep();
    quoted(k);
    s_ += ':';
    first_ = true;  // the value takes no comma
    return *this;
  }
  Json& num(double v) {
    sep();
    if (!std::isfinite(v)) {
      s_ += "null";
      return *this;
    }
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, static_cast<float>(v));
    s_.append(buf, r.ptr);
    return *this;
  }
  Json& integer(int64_t v) {
    sep();
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    s_.append(buf, r.ptr);
    return *this;
  }
  Json& boolean(bool b) { sep(); s_ += b ? "true" : "false"; return *this; }
  Json& null() { sep(); s_ += "null"; return *this; }
  Json& str(std::string_view v) { sep(); quoted(v); return *this; }
  // Bytes as base64 (RFC 4648), how JSON messages carry `bytes` fields.
  Json& base64(const uint8_t* data, size_t size);
  // {"sec": .., "nsec": ..} of t_ns (Foxglove's time).
  Json& time(uint64_t t_ns) {
    open().key("sec").integer(static_cast<int64_t>(t_ns / 1000000000u));
    key("nsec").integer(static_cast<int64_t>(t_ns % 1000000000u));
    return close();
  }
  Json& vec3(double x, double y, double z) {
    open().key("x").num(x).key("y").num(y).key("z").num(z);
    return close();
  }
  Json& quat(double x, double y, double z, double w) {
    open().key("x").num(x).key("y").num(y).key("z").num(z).key("w").num(w);
    return close();
  }

 private:
  void sep() {
    if (!first_) s_ += ',';
    first_ = false;
  }
  void quoted(std::string_view v) { common::json::appendQuoted(s_, v); }
  std::string s_;
  bool first_ = true;
};

}  // namespace simswift::record
