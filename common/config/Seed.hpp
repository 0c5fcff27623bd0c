// The one reader of a seed written as text (command lines, a robot's setup
// file): a whole decimal number of up to 64 bits, every value exact
// (a double holds whole numbers exactly only up to 2^53, and robot seeds
// are derived by multiplying, so they pass it).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace common::config {

constexpr const char* kSeedRange = "a whole number in [0, 18446744073709551615]";

// The seed `text` spells (digits only: no sign, no exponent, no spaces), or
// nothing if it spells none or one beyond 2^64 - 1.
std::optional<uint64_t> parseSeed(const std::string& text);

}  // namespace common::config
