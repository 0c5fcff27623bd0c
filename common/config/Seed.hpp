// The one reader of a seed written as text (command lines; scenario,
// experiment, test and robot setup files): a whole decimal number of up to
// 64 bits, every value exact (a double holds whole numbers exactly only up
// to 2^53, and derived seeds, common/random/DeriveSeed.hpp, use all 64 bits).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "common/config/YamlReader.hpp"

namespace common::config {

constexpr const char* kSeedRange = "a whole number in [0, 18446744073709551615]";

// The seed `text` spells (digits only: no sign, no exponent, no spaces), or
// nothing if it spells none or one beyond 2^64 - 1.
std::optional<uint64_t> parseSeed(const std::string& text);

// The seed at `key` of a config map by parseSeed's rule (`def` if absent),
// read from the YAML text, never through a double; anything else throws
// ConfigError "file:line: key: must be a whole number in [0, ...] (got '1.5')".
uint64_t readSeed(const YamlReader& r, const std::string& key, uint64_t def);
// The same for a required key ("missing required key" if absent).
uint64_t readSeed(const YamlReader& r, const std::string& key);

}  // namespace common::config
