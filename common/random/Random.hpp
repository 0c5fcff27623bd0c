// A seeded random source for the robot code's filters: SplitMix64 (fixed
// algorithm, so the same seed gives the same numbers on every platform and
// standard library) with uniform and Gaussian draws.
#pragma once

#include <cmath>
#include <cstdint>

#include "common/random/SplitMix64.hpp"

namespace common::random {

class Random {
 public:
  explicit Random(uint64_t seed = 1) : state_(seed) {}
  uint64_t next() {
    const uint64_t z = splitmix64(state_);
    state_ += kGoldenGamma;
    return z;
  }
  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Standard normal (Box-Muller, one value per call).
  double gaussian() {
    const double u1 = 1.0 - uniform();  // (0, 1]
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }
  double gaussian(double sigma) { return sigma * gaussian(); }

 private:
  uint64_t state_;
};

}  // namespace common::random
