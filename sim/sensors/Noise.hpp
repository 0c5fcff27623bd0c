// Seeded sensor noise and quantisation. Pure logic, no ODE.
//
// std::normal_distribution is implementation-defined (libstdc++ and libc++
// give different sequences for one seed), so the Gaussian here is our own
// Box-Muller over std::mt19937_64, whose output is fixed by the standard.
// Every sensor of every robot owns its own stream, seeded from
// (config seed, robot index, sensor id): adding a robot or a sensor leaves the
// other streams untouched, so runs stay comparable.
#pragma once

#include <cstdint>
#include <random>

namespace simswift::sensors {

// Identifies one noise stream of a robot. Append only: the value is part of
// the seed, so renumbering would change every recorded run.
enum class StreamId : uint32_t {
  Gyroscope = 1,
  Accelerometer = 2,
  Angle = 3,
  LeftFsr = 4,
  RightFsr = 5,
  LeftSonar = 6,
  RightSonar = 7,
  JointEncoders = 8,
};

// Seed of one stream, a pure function of its three inputs.
uint64_t streamSeed(uint64_t seed, int robot, StreamId id);

class NoiseStream {
 public:
  explicit NoiseStream(uint64_t seed = 0) : engine_(seed) {}
  NoiseStream(uint64_t seed, int robot, StreamId id) : engine_(streamSeed(seed, robot, id)) {}

  // Uniform in [0, 1) with 53 random bits.
  double uniform();
  // Standard normal (mean 0, sigma 1), Box-Muller; the pair's second value
  // is kept for the next call.
  double gaussian();
  // bias + sigma * N(0,1); when `enabled` is false returns exactly `value`
  // and draws nothing (so a noiseless run is exact).
  double perturb(double value, double sigma, double bias, bool enabled);

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

// Rounds `value` to the nearest multiple of `step` (> 0); step <= 0 returns
// value unchanged.
double quantise(double value, double step);

}  // namespace simswift::sensors
