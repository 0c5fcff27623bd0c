// The V5's inertial slots (common/libagent/Inertial.hpp) from a torso turned
// (yaw both ways), tilted and rolling or pitching (both ways) and lying (face
// down, on its back), against the NAO's conventions as its clients read them:
// GyroscopeZ negative for an anti-clockwise turn (rUNSWift's MotionOdometry,
// B-Human's V5 provider), AccelerometerX/Z negated and Y kept against the
// specific force (B-Human's V5 provider: upright AccelerometerZ = -9.81),
// GyrX/GyrY and AccX/Y/Z in raw counts (rUNSWift's FilteredTouch: rad/s =
// DEG2RAD(GyrX) / 2.35; 65 counts per g), AngleX/AngleY right-handed.
// Pure maths: ImuModel over one 10 ms tick, then writeV5InertialSlots.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "common/libagent/Inertial.hpp"
#include "sim/sensors/Imu.hpp"
#include "sim/sensors/SensorConfig.hpp"

using namespace simswift::sensors;
using Eigen::AngleAxisd;
using Eigen::Matrix3d;
using Eigen::Vector3d;
namespace S = common::libagent::Sensors;

namespace {

constexpr double kG = 9.81;   // m/s^2
constexpr double kDt = 0.01;  // s
// rUNSWift's conversions, restated from their public code (FilteredTouch).
double filteredTouchRate(float gyr) { return gyr * M_PI / 180.0 / 2.35; }  // rad/s
constexpr double kCountsPerG = 65.0;

using Slots = std::array<float, common::libagent::kNumSensors>;

// The slots after the torso went from `from` to `to` in one tick, at rest
// otherwise (no linear acceleration), noise-free.
Slots measure(const Matrix3d& from, const Matrix3d& to, int gyr_sign = 1, int acc_sign = 1) {
  ImuModel m;
  m.reset(from, Vector3d::Zero());
  m.update(from, Vector3d::Zero(), Vector3d::Zero(), kDt, kG);  // primes the orientation history
  const ImuSample t = m.update(to, Vector3d::Zero(), Vector3d::Zero(), kDt, kG);
  Slots s{};
  s.fill(1234.5f);  // every inertial slot must be written
  writeV5InertialSlots(t, gyr_sign, acc_sign, s.data());
  return s;
}
Matrix3d rot(double angle, const Vector3d& axis) { return AngleAxisd(angle, axis).toRotationMatrix(); }

// Body rates and tilt are read back as the robot code reads them.
void expectRawMatchesCalibrated(const Slots& s) {
  EXPECT_NEAR(filteredTouchRate(s[S::InertialSensor_GyrX]), s[S::InertialSensor_GyroscopeX], 1e-5);
  EXPECT_NEAR(filteredTouchRate(s[S::InertialSensor_GyrY]), s[S::InertialSensor_GyroscopeY], 1e-5);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(s[S::InertialSensor_AccX + k] * kG / kCountsPerG, s[S::InertialSensor_AccelerometerX + k], 1e-4)
        << "axis " << k;
  EXPECT_EQ(s[S::InertialSensor_GyrRef], 0.0f);
}

}  // namespace

TEST(InertialSlots, UprightAtRestReadsMinusOneGOnZ) {
  const Slots s = measure(Matrix3d::Identity(), Matrix3d::Identity());
  EXPECT_NEAR(s[S::InertialSensor_AccelerometerZ], -kG, 1e-5);
  EXPECT_NEAR(s[S::InertialSensor_AccelerometerX], 0.0, 1e-5);
  EXPECT_NEAR(s[S::InertialSensor_AccelerometerY], 0.0, 1e-5);
  EXPECT_NEAR(s[S::InertialSensor_AccZ], -kCountsPerG, 1e-3);  // raw: one g = 65 counts
  for (int k : {S::InertialSensor_GyroscopeX, S::InertialSensor_GyroscopeY, S::InertialSensor_GyroscopeZ,
                S::InertialSensor_GyrX, S::InertialSensor_GyrY, S::InertialSensor_AngleX, S::InertialSensor_AngleY})
    EXPECT_NEAR(s[k], 0.0, 1e-6) << common::libagent::Sensors::kNames[k];
  expectRawMatchesCalibrated(s);
}

// Turning anti-clockwise (left) at 1 rad/s reads GyroscopeZ = -1 on the V5;
// rUNSWift's MotionOdometry (turn per 10 ms frame = -0.01 * GyroscopeZ)
// then reads +0.01 rad, the walk's anti-clockwise-positive sense. Clockwise
// the other way. The heading the robot starts from does not matter.
TEST(InertialSlots, TurningLeftReadsNegativeGyroscopeZAndRightPositive) {
  for (double heading : {0.0, 2.0, -2.8}) {
    for (double rate : {1.0, -1.0, 0.3, -0.3}) {
      const Matrix3d r0 = rot(heading, Vector3d::UnitZ());
      const Slots s = measure(r0, rot(rate * kDt, Vector3d::UnitZ()) * r0);
      const std::string at = "heading " + std::to_string(heading) + " rate " + std::to_string(rate);
      EXPECT_NEAR(s[S::InertialSensor_GyroscopeZ], -rate, 1e-6) << at;
      EXPECT_NEAR(-0.01 * s[S::InertialSensor_GyroscopeZ], rate * kDt, 1e-8) << at;  // rUNSWift's odometry
      EXPECT_NEAR(s[S::InertialSensor_GyroscopeX], 0.0, 1e-6) << at;
      EXPECT_NEAR(s[S::InertialSensor_GyroscopeY], 0.0, 1e-6) << at;
      EXPECT_NEAR(s[S::InertialSensor_AccelerometerZ], -kG, 1e-5) << at;
      // The robot code's reader gives the right-handed (anti-clockwise-positive) rate.
      EXPECT_NEAR(common::libagent::inertial::bodyRates(s.data()).z, rate, 1e-6) << at;
      expectRawMatchesCalibrated(s);
    }
  }
}

// Rolling to the robot's right (left side rising) and pitching forward read
// positive GyroscopeX / GyroscopeY, and the raw GyrX / GyrY carry the same
// rate in counts: rUNSWift's FilteredTouch conversion gives it back.
TEST(InertialSlots, RollingAndPitchingBothWays) {
  for (double rate : {0.5, -0.5, 2.0, -2.0}) {
    const Slots roll = measure(Matrix3d::Identity(), rot(rate * kDt, Vector3d::UnitX()));
    EXPECT_NEAR(roll[S::InertialSensor_GyroscopeX], rate, 1e-6) << rate;
    EXPECT_NEAR(roll[S::InertialSensor_GyrX], rate * 2.35 * 180.0 / M_PI, 1e-3) << rate;  // ~134.6 counts per rad/s
    EXPECT_NEAR(filteredTouchRate(roll[S::InertialSensor_GyrX]), rate, 1e-5) << rate;
    EXPECT_NEAR(roll[S::InertialSensor_GyroscopeY], 0.0, 1e-6);
    EXPECT_NEAR(roll[S::InertialSensor_GyroscopeZ], 0.0, 1e-6);
    EXPECT_GT(roll[S::InertialSensor_AngleX] * rate, 0) << "tipping right reads AngleX > 0";
    expectRawMatchesCalibrated(roll);

    const Slots pitch = measure(Matrix3d::Identity(), rot(rate * kDt, Vector3d::UnitY()));
    EXPECT_NEAR(pitch[S::InertialSensor_GyroscopeY], rate, 1e-6) << rate;
    EXPECT_NEAR(pitch[S::InertialSensor_GyrY], rate * 2.35 * 180.0 / M_PI, 1e-3) << rate;
    EXPECT_NEAR(filteredTouchRate(pitch[S::InertialSensor_GyrY]), rate, 1e-5) << rate;
    EXPECT_NEAR(pitch[S::InertialSensor_GyroscopeX], 0.0, 1e-6);
    EXPECT_GT(pitch[S::InertialSensor_AngleY] * rate, 0) << "tipping forward reads AngleY > 0";
    expectRawMatchesCalibrated(pitch);
  }
}

// Standing tilted, still: AngleX / AngleY give the tilt; the accelerometer
// reads gravity with the V5's signs: leaning forward AccelerometerX > 0,
// leaning right AccelerometerY > 0, AccelerometerZ = -g cos(tilt).
TEST(InertialSlots, TiltedBothWaysReadsAnglesAndGravity) {
  for (double a : {0.3, -0.3, 0.7, -0.7}) {
    const Matrix3d rolled = rot(a, Vector3d::UnitX());  // a > 0: leaning to the robot's right
    const Slots r = measure(rolled, rolled);
    EXPECT_NEAR(r[S::InertialSensor_AngleX], a, 1e-6) << a;
    EXPECT_NEAR(r[S::InertialSensor_AngleY], 0.0, 1e-6) << a;
    EXPECT_NEAR(r[S::InertialSensor_AccelerometerY], kG * std::sin(a), 1e-5) << a;
    EXPECT_NEAR(r[S::InertialSensor_AccelerometerX], 0.0, 1e-5) << a;
    EXPECT_NEAR(r[S::InertialSensor_AccelerometerZ], -kG * std::cos(a), 1e-5) << a;
    EXPECT_NEAR(r[S::InertialSensor_AccY], kCountsPerG * std::sin(a), 1e-3) << a;
    EXPECT_NEAR(r[S::InertialSensor_GyroscopeX], 0.0, 1e-6) << "still";
    expectRawMatchesCalibrated(r);

    const Matrix3d pitched = rot(a, Vector3d::UnitY());  // a > 0: leaning forward
    const Slots p = measure(pitched, pitched);
    EXPECT_NEAR(p[S::InertialSensor_AngleY], a, 1e-6) << a;
    EXPECT_NEAR(p[S::InertialSensor_AngleX], 0.0, 1e-6) << a;
    EXPECT_NEAR(p[S::InertialSensor_AccelerometerX], kG * std::sin(a), 1e-5) << a;
    EXPECT_NEAR(p[S::InertialSensor_AccelerometerY], 0.0, 1e-5) << a;
    EXPECT_NEAR(p[S::InertialSensor_AccelerometerZ], -kG * std::cos(a), 1e-5) << a;
    EXPECT_NEAR(p[S::InertialSensor_AccX], kCountsPerG * std::sin(a), 1e-3) << a;
    expectRawMatchesCalibrated(p);
  }
}

// Lying still: face down AngleY ~ +pi/2 and AccelerometerX ~ +g; on the
// back AngleY ~ -pi/2 and AccelerometerX ~ -g; AccelerometerZ ~ 0 either
// way. On its sides AngleX ~ +-pi/2, AccelerometerY ~ +-g.
TEST(InertialSlots, LyingFaceDownOnTheBackAndOnItsSides) {
  const Matrix3d face_down = rot(M_PI / 2, Vector3d::UnitY());  // torso x axis points at the carpet
  const Slots d = measure(face_down, face_down);
  EXPECT_NEAR(d[S::InertialSensor_AngleY], M_PI / 2, 1e-3);
  EXPECT_NEAR(d[S::InertialSensor_AccelerometerX], kG, 1e-4);
  EXPECT_NEAR(d[S::InertialSensor_AccelerometerZ], 0.0, 1e-4);
  EXPECT_NEAR(d[S::InertialSensor_AccX], kCountsPerG, 1e-2);
  expectRawMatchesCalibrated(d);

  const Matrix3d on_back = rot(-M_PI / 2, Vector3d::UnitY());
  const Slots b = measure(on_back, on_back);
  EXPECT_NEAR(b[S::InertialSensor_AngleY], -M_PI / 2, 1e-3);
  EXPECT_NEAR(b[S::InertialSensor_AccelerometerX], -kG, 1e-4);
  EXPECT_NEAR(b[S::InertialSensor_AccelerometerZ], 0.0, 1e-4);
  EXPECT_NEAR(b[S::InertialSensor_AccX], -kCountsPerG, 1e-2);
  expectRawMatchesCalibrated(b);

  for (double side : {1.0, -1.0}) {  // +1: on its right side
    const Matrix3d lying = rot(side * M_PI / 2, Vector3d::UnitX());
    const Slots l = measure(lying, lying);
    EXPECT_NEAR(l[S::InertialSensor_AngleX], side * M_PI / 2, 1e-3) << side;
    EXPECT_NEAR(l[S::InertialSensor_AccelerometerY], side * kG, 1e-4) << side;
    EXPECT_NEAR(l[S::InertialSensor_AccelerometerZ], 0.0, 1e-4) << side;
  }
}

// The raw values' sign against the calibrated ones is configurable (not
// settled by a public source): -1 flips GyrX/GyrY or AccX/Y/Z and nothing else.
TEST(InertialSlots, RawSignsAreConfigurable) {
  const Matrix3d tilted = rot(0.2, Vector3d::UnitX()) * rot(0.1, Vector3d::UnitY());
  const Matrix3d moved = rot(0.01, Vector3d(1, 2, 3).normalized()) * tilted;
  const Slots plus = measure(tilted, moved, 1, 1);
  const Slots gyr = measure(tilted, moved, -1, 1);
  const Slots acc = measure(tilted, moved, 1, -1);
  for (int k = 0; k < common::libagent::kNumSensors; ++k) {
    const bool raw_gyr = k == S::InertialSensor_GyrX || k == S::InertialSensor_GyrY;
    const bool raw_acc = k >= S::InertialSensor_AccX && k <= S::InertialSensor_AccZ;
    EXPECT_EQ(gyr[k], raw_gyr ? -plus[k] : plus[k]) << S::kNames[k];
    EXPECT_EQ(acc[k], raw_acc ? -plus[k] : plus[k]) << S::kNames[k];
  }
  EXPECT_GT(std::fabs(plus[S::InertialSensor_GyrX]), 1.0f);
  SensorConfig c;
  c.gyr_raw_sign = 0;
  try {
    c.validate();
    FAIL() << "gyr_raw_sign 0 accepted";
  } catch (const SensorConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("gyr_raw_sign"), std::string::npos) << e.what();
  }
  c.gyr_raw_sign = -1;
  c.acc_raw_sign = 2;
  EXPECT_THROW(c.validate(), SensorConfigError);
}
