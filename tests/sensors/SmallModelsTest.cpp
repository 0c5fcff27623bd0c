// Hand mapping, bumpers, battery, config checks.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/sensors/Battery.hpp"
#include "sim/sensors/Buttons.hpp"
#include "sim/sensors/JointEncoders.hpp"
#include "sim/sensors/SensorConfig.hpp"

using namespace simswift::sensors;

TEST(JointModels, HandReadsFractionOpen) {
  EXPECT_DOUBLE_EQ(encoderValue(0.5, true, 0.0, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(encoderValue(0.25, true, 0.0, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(encoderValue(0.7, false, -1.0, 1.0), 0.7);
}

TEST(Bumpers, ToeHalvesPerFoot) {
  const BumperHit l = bumperFor({0.09, 0.03, -0.04}, true, 0.07);
  EXPECT_TRUE(l.left);
  EXPECT_FALSE(l.right);
  const BumperHit r = bumperFor({0.09, -0.03, -0.04}, false, 0.07);
  EXPECT_TRUE(r.right);
  EXPECT_FALSE(r.left);
  const BumperHit heel = bumperFor({0.0, 0.0, -0.04}, true, 0.07);
  EXPECT_FALSE(heel.left || heel.right);
}

TEST(BatteryModel, DrainsAtTheConfiguredCurrent) {
  Battery b(1.0, -2.25, 2.25);  // 1 C: empty in one hour
  for (int i = 0; i < 180000; ++i) b.step(0.01);  // 30 min
  EXPECT_NEAR(b.charge(), 0.5, 1e-6);
  EXPECT_DOUBLE_EQ(b.current(), -2.25);
  for (int i = 0; i < 360000; ++i) b.step(0.01);
  EXPECT_EQ(b.charge(), 0.0);
}

TEST(Config, DefaultsValidateAndBadFieldsAreNamed) {
  SensorConfig c;
  EXPECT_NO_THROW(c.validate());
  c.gyro.sigma = -1;
  try {
    c.validate();
    FAIL() << "negative sigma accepted";
  } catch (const SensorConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("gyro.sigma"), std::string::npos) << e.what();
  }
  SensorConfig d;
  d.sonar_max_range = 0.1;
  EXPECT_THROW(d.validate(), SensorConfigError);
}
