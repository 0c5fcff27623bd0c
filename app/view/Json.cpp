#include "app/view/Json.hpp"

#include <cctype>

namespace simswift::view::json {

namespace {

constexpr int kMaxDepth = 128;

class Validator {
 public:
  explicit Validator(std::string_view t) : t_(t) {}
  std::size_t run() {
    space();
    if (!value(0)) return i_;
    space();
    return i_ == t_.size() ? std::string_view::npos : i_;
  }

 private:
  bool value(int depth) {
    if (depth > kMaxDepth || i_ >= t_.size()) return false;
    switch (t_[i_]) {
      case '{':
        return object(depth);
      case '[':
        return array(depth);
      case '"':
        return string();
      case 't':
        return word("true");
      case 'f':
        return word("false");
      case 'n':
        return word("null");
      default:
        return number();
    }
  }
  bool object(int depth) {
    ++i_;
    space();
    if (peek('}')) return ++i_, true;
    for (;;) {
      space();
      if (!peek('"') || !string()) return false;
      space();
      if (!peek(':')) return false;
      ++i_;
      space();
      if (!value(depth + 1)) return false;
      space();
      if (peek('}')) return ++i_, true;
      if (!peek(',')) return false;
      ++i_;
    }
  }
  bool array(int depth) {
    ++i_;
    space();
    if (peek(']')) return ++i_, true;
    for (;;) {
      space();
      if (!value(depth + 1)) return false;
      space();
      if (peek(']')) return ++i_, true;
      if (!peek(',')) return false;
      ++i_;
    }
  }
  bool string() {
    ++i_;
    while (i_ < t_.size()) {
      const unsigned char c = static_cast<unsigned char>(t_[i_]);
      if (c == '"') return ++i_, true;
      if (c < 0x20) return false;
      if (c == '\\') {
        if (++i_ >= t_.size()) return false;
        const char e = t_[i_];
        if (e == 'u') {
          for (int k = 1; k <= 4; ++k)
            if (i_ + k >= t_.size() || !std::isxdigit(static_cast<unsigned char>(t_[i_ + k]))) return false;
          i_ += 4;
        } else if (std::string_view("\"\\/bfnrt").find(e) == std::string_view::npos) {
          return false;
        }
      }
      ++i_;
    }
    return false;
  }
  bool number() {
    if (peek('-')) ++i_;
    if (peek('0')) {
      ++i_;
    } else if (!digits()) {
      return false;
    }
    if (peek('.')) {
      ++i_;
      if (!digits()) return false;
    }
    if (peek('e') || peek('E')) {
      ++i_;
      if (peek('+') || peek('-')) ++i_;
      if (!digits()) return false;
    }
    return true;
  }
  bool digits() {
    const std::size_t from = i_;
    while (i_ < t_.size() && t_[i_] >= '0' && t_[i_] <= '9') ++i_;
    return i_ > from;
  }
  bool word(std::string_view w) {
    if (t_.substr(i_, w.size()) != w) return false;
    i_ += w.size();
    return true;
  }
  bool peek(char c) const { return i_ < t_.size() && t_[i_] == c; }
  void space() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\n' || t_[i_] == '\r')) ++i_;
  }

  std::string_view t_;
  std::size_t i_ = 0;
};

}  // namespace

std::size_t invalidAt(std::string_view text) { return Validator(text).run(); }

}  // namespace simswift::view::json
