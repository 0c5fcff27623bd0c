// A state hash as the C++ literal a pinned-hash test holds (0x...ull), so a
// failing test prints the value to paste when a re-pin is meant.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace simswift::testing {

inline std::string hashLiteral(uint64_t v) {
  char b[24];
  std::snprintf(b, sizeof b, "0x%016llxull", static_cast<unsigned long long>(v));
  return b;
}

}  // namespace simswift::testing
