#include "sim/sensors/Noise.hpp"

#include <cmath>

#include "common/random/DeriveSeed.hpp"

namespace simswift::sensors {

uint64_t streamSeed(uint64_t seed, int robot, StreamId id) {
  // Chained, so (robot 1, sensor 2) and (robot 2, sensor 1) do not collide.
  using common::random::deriveSeed;
  const uint64_t noise = deriveSeed(seed, common::random::seed_tag::kSensorNoise);
  const uint64_t per_robot = deriveSeed(noise, static_cast<uint64_t>(static_cast<uint32_t>(robot)));
  return deriveSeed(per_robot, static_cast<uint64_t>(id) << 32);
}

double NoiseStream::uniform() {
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

double NoiseStream::gaussian() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  // u1 in (0, 1] keeps log() finite.
  const double u1 = 1.0 - uniform();
  const double u2 = uniform();
  const double r = std::sqrt(-2.0 * std::log(u1));
  const double a = 2.0 * M_PI * u2;
  spare_ = r * std::sin(a);
  has_spare_ = true;
  return r * std::cos(a);
}

double NoiseStream::perturb(double value, double sigma, double bias, bool enabled) {
  if (!enabled) return value;
  return value + bias + (sigma > 0 ? sigma * gaussian() : 0.0);
}

double quantise(double value, double step) {
  if (!(step > 0)) return value;
  return std::round(value / step) * step;
}

}  // namespace simswift::sensors
