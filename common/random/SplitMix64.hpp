// SplitMix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014; the finaliser as in Vigna's public-domain
// splitmix64.c): a bijective 64-bit mixer, so distinct inputs give
// well-spread, distinct outputs. The one definition for the robot code's
// random source and the simulator's seed derivations.
#pragma once

#include <cstdint>

namespace common::random {

constexpr uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ULL;  // 2^64 / golden ratio, odd

// The SplitMix64 output for state `x` (the generator's state advances by
// kGoldenGamma per draw).
constexpr uint64_t splitmix64(uint64_t x) {
  x += kGoldenGamma;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace common::random
