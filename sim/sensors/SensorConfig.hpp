// Typed configuration of a simulated NAO's non-camera sensors. Defaults are
// realistic (noise on) and documented with their units; `validate()` names
// the offending field.
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace simswift::sensors {

// Additive Gaussian noise: reading = truth + bias + sigma * N(0, 1).
struct NoiseSpec {
  double sigma = 0;  // standard deviation, in the sensor's unit
  double bias = 0;   // constant offset, in the sensor's unit
};

struct SensorConfigError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct SensorConfig {
  // ---- Noise
  bool noise = true;   // master switch: false = every reading exact (quantisation stays)
  uint64_t seed = 1;   // streams derive from (seed, robot index, sensor id)
  NoiseSpec gyro{0.005, 0.0};    // rad/s, per axis
  NoiseSpec accel{0.05, 0.0};    // m/s^2, per axis
  NoiseSpec angle{0.002, 0.0};   // rad, AngleX and AngleY
  NoiseSpec fsr{0.05, 0.0};      // N, per sensor (before the 0..max clamp)
  NoiseSpec sonar{0.01, 0.0};    // m, per echo
  NoiseSpec encoder{0.0, 0.0};   // rad, before quantisation (the MRE's own noise
                                 // is below one count, so quantisation is the error)

  // ---- The V5's legacy raw inertial values, GyrX/GyrY and AccX/Y/Z (counts;
  // common/libagent/Inertial.hpp): their sign against GyroscopeX/Y and
  // AccelerometerX/Y/Z is not settled by a public source. +1 (default) = the
  // same sign as the calibrated values, -1 = the opposite.
  int gyr_raw_sign = +1;
  int acc_raw_sign = +1;

  // ---- Joint encoders: the NAO V5 reads joint angles with 12-bit magnetic
  // rotary encoders on the joint axis, 4096 counts per turn.
  double encoder_step = 2.0 * M_PI / 4096.0;  // rad per count; <= 0 = no quantisation

  // ---- FSR
  double fsr_max = 25.0;          // N, each sensor saturates here
  double fsr_unloaded = 0.5;      // N: below this total a foot's CoP reads 0

  // ---- Foot bumpers: a non-ground contact ahead of this x (m, ankle frame)
  // presses the bumper of its half of the toe.
  double bumper_min_x = 0.07;     // m (the sole's toe is at 0.110)
  double bumper_min_force = 0.5;  // N

  // ---- Battery
  double battery_start = 1.0;         // charge fraction 0..1 at the start
  double battery_current = -1.5;      // A (negative = discharging)
  double battery_capacity = 2.25;     // Ah (NAO V5 battery: 21.6 V, 2.25 Ah)

  // ---- Sonar
  double sonar_min_range = 0.20;  // m: closer echoes read this (NAO V5: no distance below 0.20)
  double sonar_max_range = 0.80;  // m: beyond this, no echo (kSonarNoEcho)
  double sonar_cone = 60.0 * M_PI / 180.0;   // rad, full opening angle
  double sonar_yaw = 25.0 * M_PI / 180.0;    // rad, each beam's axis left/right of straight ahead
  double sonar_pitch = 0.0;                  // rad, axis tilt down (+) in torso axes
  double sonar_echo_separation = 0.05;       // m: closer hits merge into one echo
  int sonar_period_ticks = 10;               // the NAO refreshes sonar every 100 ms

  // Throws SensorConfigError naming the first bad field.
  void validate() const {
    auto fail = [](const std::string& field, const std::string& why) {
      throw SensorConfigError("SensorConfig." + field + ": " + why);
    };
    auto nonneg = [&](const char* field, double v) {
      if (!(v >= 0) || !std::isfinite(v)) fail(field, "must be finite and >= 0, got " + std::to_string(v));
    };
    auto positive = [&](const char* field, double v) {
      if (!(v > 0) || !std::isfinite(v)) fail(field, "must be finite and > 0, got " + std::to_string(v));
    };
    nonneg("gyro.sigma", gyro.sigma);
    nonneg("accel.sigma", accel.sigma);
    nonneg("angle.sigma", angle.sigma);
    nonneg("fsr.sigma", fsr.sigma);
    nonneg("sonar.sigma", sonar.sigma);
    nonneg("encoder.sigma", encoder.sigma);
    auto sign = [&](const char* field, int v) {
      if (v != 1 && v != -1) fail(field, "must be +1 or -1, got " + std::to_string(v));
    };
    sign("gyr_raw_sign", gyr_raw_sign);
    sign("acc_raw_sign", acc_raw_sign);
    if (!std::isfinite(encoder_step)) fail("encoder_step", "must be finite");
    positive("fsr_max", fsr_max);
    nonneg("fsr_unloaded", fsr_unloaded);
    nonneg("bumper_min_force", bumper_min_force);
    if (!(battery_start >= 0 && battery_start <= 1)) fail("battery_start", "must be in 0..1");
    positive("battery_capacity", battery_capacity);
    positive("sonar_min_range", sonar_min_range);
    if (!(sonar_max_range > sonar_min_range)) fail("sonar_max_range", "must exceed sonar_min_range");
    if (!(sonar_cone > 0 && sonar_cone < M_PI)) fail("sonar_cone", "must be in (0, pi) rad");
    positive("sonar_echo_separation", sonar_echo_separation);
    if (sonar_period_ticks < 1) fail("sonar_period_ticks", "must be >= 1");
  }
};

}  // namespace simswift::sensors
