// FSR distribution, saturation and centre of pressure.
#include <gtest/gtest.h>

#include "sim/sensors/Fsr.hpp"

using namespace simswift::sensors;

namespace {
double sum(const std::array<double, 4>& f) { return f[0] + f[1] + f[2] + f[3]; }
// Sole centre (m, left ankle frame): 110 mm ahead / 50 behind, 50.02 mm
// outside / 38.78 inside (Aldebaran's NAO V5 (H25) documentation).
const Eigen::Vector2d kLeftSoleCentre(0.030, 0.00562);
}  // namespace

TEST(Fsr, CentreContactSplitsIntoFourSummingToTheForce) {
  const FsrLayout l = FsrLayout::left();
  std::array<double, 4> f{};
  distributeForce(l, kLeftSoleCentre, 52.0, f);
  EXPECT_NEAR(sum(f), 52.0, 0.52);  // within 1%
  for (double v : f) {
    EXPECT_GT(v, 5.0);   // all four share a centred load
    EXPECT_LT(v, 25.0);  // none saturates at 52 N
  }
  const Eigen::Vector2d cop = centreOfPressure(l, f, 0.5);
  EXPECT_NEAR(cop.x(), kLeftSoleCentre.x(), 1e-6);
  EXPECT_NEAR(cop.y(), kLeftSoleCentre.y(), 1e-6);
}

TEST(Fsr, CopFollowsTheContactInsideTheSensorQuad) {
  for (const FsrLayout& l : {FsrLayout::left(), FsrLayout::right()}) {
    for (double x : {-0.02, 0.0, 0.03, 0.06}) {
      for (double y : {-0.015, 0.0, 0.015}) {
        std::array<double, 4> f{};
        distributeForce(l, {x, y}, 20.0, f);
        EXPECT_NEAR(sum(f), 20.0, 1e-9);
        const Eigen::Vector2d cop = centreOfPressure(l, f, 0.5);
        EXPECT_NEAR(cop.x(), x, 1e-6);
        EXPECT_NEAR(cop.y(), y, 1e-6);
      }
    }
  }
}

TEST(Fsr, TwoContactsGiveTheirForceWeightedMean) {
  const FsrLayout l = FsrLayout::left();
  std::array<double, 4> f{};
  distributeForce(l, {0.06, 0.0}, 30.0, f);
  distributeForce(l, {-0.02, 0.02}, 10.0, f);
  const Eigen::Vector2d cop = centreOfPressure(l, f, 0.5);
  EXPECT_NEAR(cop.x(), (0.06 * 30 - 0.02 * 10) / 40, 1e-6);
  EXPECT_NEAR(cop.y(), (0.0 * 30 + 0.02 * 10) / 40, 1e-6);
}

TEST(Fsr, ContactAtASensorLoadsOnlyThatSensor) {
  const FsrLayout l = FsrLayout::left();
  for (int i = 0; i < 4; ++i) {
    std::array<double, 4> f{};
    distributeForce(l, l.sensor[i], 10.0, f);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(f[k], k == i ? 10.0 : 0.0, 1e-9);
  }
}

TEST(Fsr, ContactOutsideIsClampedToTheNearestEdge) {
  const FsrLayout l = FsrLayout::left();
  std::array<double, 4> f{};
  distributeForce(l, {0.105, 0.0}, 10.0, f);  // on the toe, ahead of the front sensors
  EXPECT_NEAR(f[FrontLeft] + f[FrontRight], 10.0, 1e-9);
  EXPECT_NEAR(f[RearLeft] + f[RearRight], 0.0, 1e-9);
}

TEST(Fsr, PullingForceIsIgnored) {
  std::array<double, 4> f{};
  distributeForce(FsrLayout::left(), kLeftSoleCentre, -5.0, f);
  EXPECT_EQ(sum(f), 0.0);
}

TEST(Fsr, SaturatesAt25N) {
  const FsrLayout l = FsrLayout::left();
  std::array<double, 4> f{};
  distributeForce(l, l.sensor[FrontLeft], 60.0, f);
  distributeForce(l, kLeftSoleCentre, 40.0, f);
  saturate(f, 25.0);
  EXPECT_DOUBLE_EQ(f[FrontLeft], 25.0);
  for (double v : f) {
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 25.0);
  }
  std::array<double, 4> neg{{-0.2, 1, 2, 3}};
  saturate(neg, 25.0);
  EXPECT_EQ(neg[0], 0.0);
}

TEST(Fsr, UnloadedFootHasZeroCop) {
  std::array<double, 4> f{{0.1, 0.05, 0.0, 0.1}};
  const Eigen::Vector2d cop = centreOfPressure(FsrLayout::left(), f, 0.5);
  EXPECT_EQ(cop.x(), 0.0);
  EXPECT_EQ(cop.y(), 0.0);
}

TEST(Fsr, RightFootMirrorsLeft) {
  const FsrLayout l = FsrLayout::left(), r = FsrLayout::right();
  EXPECT_DOUBLE_EQ(r.sensor[FrontLeft].y(), -l.sensor[FrontRight].y());
  EXPECT_DOUBLE_EQ(r.sensor[RearRight].y(), -l.sensor[RearLeft].y());
  EXPECT_GT(r.sensor[FrontLeft].y(), r.sensor[FrontRight].y());  // left is +y on both feet
  std::array<double, 4> fl{}, fr{};
  distributeForce(l, {0.01, 0.012}, 30, fl);
  distributeForce(r, {0.01, -0.012}, 30, fr);
  EXPECT_NEAR(fl[FrontLeft], fr[FrontRight], 1e-9);
  EXPECT_NEAR(fl[RearRight], fr[RearLeft], 1e-9);
}
