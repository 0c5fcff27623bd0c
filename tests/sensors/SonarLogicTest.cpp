// Sonar fan geometry and echo assembly, with a fake ray caster.
#include <gtest/gtest.h>

#include <cmath>

#include "common/libagent/AgentShared.hpp"
#include "sim/sensors/Sonar.hpp"

using namespace simswift::sensors;

namespace {
constexpr float kNo = common::libagent::kSonarNoEcho;
const double kCone = 60 * M_PI / 180, kYaw = 25 * M_PI / 180;
}

TEST(SonarLogic, FanStaysInsideTheConeAndCoversIt) {
  const SonarBeam b = leftSonarBeam(kYaw, 0);
  const Eigen::Vector3d axis(std::cos(kYaw), std::sin(kYaw), 0);
  const auto fan = sonarFan(b, kCone);
  EXPECT_EQ(fan.size(), 33u);
  double widest = 0;
  for (const auto& d : fan) {
    EXPECT_NEAR(d.norm(), 1.0, 1e-12);
    const double off = std::acos(std::clamp(d.dot(axis), -1.0, 1.0));
    EXPECT_LE(off, kCone / 2 + 1e-9);
    widest = std::max(widest, off);
  }
  EXPECT_GT(widest, 0.5);  // reaches out to the 30 deg rim, not just the axis
  // The left beam looks left, the right one right.
  EXPECT_GT(leftSonarBeam(kYaw, 0).origin.y(), 0);
  EXPECT_LT(rightSonarBeam(kYaw, 0).origin.y(), 0);
  for (const auto& d : sonarFan(rightSonarBeam(kYaw, 0), kCone)) EXPECT_LT(d.y(), 0.1);
}

TEST(SonarLogic, EchoesSortMergeAndDropOutOfRange) {
  const auto e = sonarEchoes({0.61, 0.5, 0.51, 0.9, 0.1, 0.72}, 0.2, 0.8, 0.05, kNo);
  EXPECT_FLOAT_EQ(e[0], 0.2f);   // too close: reads the minimum
  EXPECT_FLOAT_EQ(e[1], 0.5f);   // 0.51 merges into 0.5
  EXPECT_FLOAT_EQ(e[2], 0.61f);
  EXPECT_FLOAT_EQ(e[3], 0.72f);
  for (int i = 4; i < 10; ++i) EXPECT_EQ(e[i], kNo);  // 0.9 is beyond range
  const auto none = sonarEchoes({}, 0.2, 0.8, 0.05, kNo);
  for (float v : none) EXPECT_EQ(v, kNo);
}

TEST(SonarLogic, CastFindsAWallAndIgnoresTheGround) {
  // Torso 0.3 m above the carpet facing +x; a wall at x = 0.6 m.
  Eigen::Isometry3d torso = Eigen::Isometry3d::Identity();
  torso.translation() = Eigen::Vector3d(0, 0, 0.3);
  const SonarBeam b = leftSonarBeam(kYaw, 0);
  auto wall = [](const Eigen::Vector3d& o, const Eigen::Vector3d& d, double range) {
    double best = -1;
    if (d.x() > 1e-9) best = (0.6 - o.x()) / d.x();
    if (d.z() < -1e-9) {
      const double g = -o.z() / d.z();
      if (best < 0 || g < best) best = g;
    }
    return best >= 0 && best <= range ? best : -1.0;
  };
  const auto hits = castSonar(b, kCone, torso, 0.8, wall);
  ASSERT_FALSE(hits.empty());
  const double origin_x = b.origin.x();
  for (double h : hits) EXPECT_GE(h, 0.6 - origin_x - 1e-9);  // no carpet hit got through
  const auto e = sonarEchoes(hits, 0.2, 0.8, 0.05, kNo);
  EXPECT_NEAR(e[0], 0.6 - origin_x, 0.01);  // the ray along the wall's normal

  auto ground_only = [](const Eigen::Vector3d& o, const Eigen::Vector3d& d, double range) {
    if (d.z() >= -1e-9) return -1.0;
    const double g = -o.z() / d.z();
    return g <= range ? g : -1.0;
  };
  EXPECT_TRUE(castSonar(b, kCone, torso, 0.8, ground_only).empty());
}
