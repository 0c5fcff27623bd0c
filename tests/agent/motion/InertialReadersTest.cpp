// The robot code reads the inertial slots as a NAO V5 gives them
// (common/libagent/Inertial.hpp): GyroscopeZ negative for an anti-clockwise
// turn, GyrX/GyrY in raw counts beside GyroscopeX/Y in rad/s. The heading
// rate, the odometry's turn and the fall's "lying still" check must read the
// NAO's convention, not a right-handed or all-rad/s one.
#include <gtest/gtest.h>

#include <cmath>

#include "common/libagent/Inertial.hpp"
#include "agent/motion/ActionMotion.hpp"
#include "agent/motion/Walk2014Generator.hpp"

using namespace agent::motion;
namespace S = common::libagent::Sensors;
namespace in = common::libagent::inertial;
namespace bb = agent::blackboard;

namespace {

// A V5's gyro slots for body rates w (rad/s, right-handed torso axes):
// GyroscopeX/Y/Z with the V5's signs, GyrX/GyrY in counts (same sign).
void setRates(common::libagent::SensorValues& s, double wx, double wy, double wz) {
  s.sensors[S::InertialSensor_GyroscopeX] = static_cast<float>(wx);
  s.sensors[S::InertialSensor_GyroscopeY] = static_cast<float>(wy);
  s.sensors[S::InertialSensor_GyroscopeZ] = static_cast<float>(-wz);  // the V5: anti-clockwise reads negative
  s.sensors[S::InertialSensor_GyrX] = static_cast<float>(in::kGyrCountsPerRadPerSecond * wx);
  s.sensors[S::InertialSensor_GyrY] = static_cast<float>(in::kGyrCountsPerRadPerSecond * wy);
}

// Both feet loaded (kg, the NAO's FSR unit: 5.3 kg over eight sensors).
common::libagent::SensorValues standing(const common::libagent::JointValues& joints) {
  common::libagent::SensorValues s{};
  s.joints = joints;
  for (int i = 0; i < 4; ++i) {
    s.sensors[S::LFoot_FSR_FrontLeft + i] = 0.66f;
    s.sensors[S::RFoot_FSR_FrontLeft + i] = 0.66f;
  }
  return s;
}

}  // namespace

TEST(InertialReaders, BodyRatesUndoTheV5Signs) {
  common::libagent::SensorValues s{};
  setRates(s, 0.1, -0.2, 0.7);
  const in::BodyRates w = in::bodyRates(s.sensors);
  EXPECT_DOUBLE_EQ(w.x, static_cast<float>(0.1));
  EXPECT_DOUBLE_EQ(w.y, static_cast<float>(-0.2));
  EXPECT_DOUBLE_EQ(w.z, static_cast<float>(0.7));
}

// Turning left (anti-clockwise) at 0.5 rad/s, a V5 reads GyroscopeZ = -0.5:
// the heading rate is +0.5, upright, tilted or lying.
TEST(InertialReaders, HeadingRateOfALeftTurnIsPositive) {
  for (double wz : {0.5, -0.5}) {
    common::libagent::SensorValues s{};
    setRates(s, 0, 0, wz);
    EXPECT_NEAR(headingRate(s.sensors), wz, 1e-6) << wz;
    s.sensors[S::InertialSensor_AngleX] = 0.05f;  // walking: a few degrees of roll and pitch
    s.sensors[S::InertialSensor_AngleY] = -0.04f;
    EXPECT_NEAR(headingRate(s.sensors), wz * std::cos(0.05) / std::cos(0.04), 1e-6) << wz;
    s.sensors[S::InertialSensor_AngleY] = 1.5f;  // lying face down
    EXPECT_NEAR(headingRate(s.sensors), wz, 1e-6) << wz;
  }
}

// The walk's odometry turn comes from the gyro while stepping: a body
// turning anti-clockwise at 0.4 rad/s (GyroscopeZ = -0.4 on the V5) must
// give a positive turn of about 0.4 rad/s times the stepping time.
TEST(InertialReaders, WalkOdometryTurnsTheWayTheBodyTurns) {
  for (double wz : {0.4, -0.4}) {
    ActionMotion motion;
    bb::MotionRequest req;
    req.body.type = bb::ActionType::WALK;
    req.body.turn = static_cast<float>(wz);
    motion.setRequest(req);
    common::libagent::JointValues cmd{};
    common::libagent::SensorValues s = standing(cmd);
    double stepping = 0;
    for (int t = 0; t < 400; ++t) {
      s.joints = cmd;
      setRates(s, 0, 0, t >= 100 ? wz : 0.0);  // the body turns from 1 s on
      motion.tickSeconds(s, t * 0.01, cmd);
      if (t >= 100 && motion.state().walk_stepping) stepping += 0.01;
    }
    ASSERT_GT(stepping, 2.0) << "the walk did not step";
    const double turned = motion.state().odometry.theta;
    EXPECT_GT(turned * wz, 0) << "odometry turned against the body, rate " << wz;
    EXPECT_NEAR(turned, wz * stepping, 0.25 * std::fabs(wz) * stepping) << wz;
  }
}

// A fallen robot gets up once it lies still: its roll and pitch rate below
// settle_rate (0.6 rad/s). On a V5 the raw GyrY holds counts (~134.6 per
// rad/s): 0.3 rad/s is 40 counts, which is still.
TEST(InertialReaders, LyingStillIsReadFromTheCalibratedGyroscope) {
  ActionMotion motion;
  bb::MotionRequest req;
  req.body.type = bb::ActionType::STAND;
  motion.setRequest(req);
  common::libagent::JointValues cmd{};
  common::libagent::SensorValues s = standing(cmd);
  for (int t = 0; t < 50; ++t) motion.tickSeconds(s, t * 0.01, cmd);
  s.sensors[S::InertialSensor_AngleY] = 0.9f;  // tipping forward fast
  setRates(s, 0, 3.0, 0);
  motion.tickSeconds(s, 0.5, cmd);
  ASSERT_EQ(motion.mode(), ActionMotion::Mode::Falling);
  s.sensors[S::InertialSensor_AngleY] = 1.5f;  // face down, rocking slightly
  setRates(s, 0.1, 0.3, 0);
  double t = 0.51;
  for (int i = 0; i < 60; ++i, t += 0.01) motion.tickSeconds(s, t, cmd);
  EXPECT_EQ(motion.mode(), ActionMotion::Mode::Getup);
  EXPECT_EQ(motion.state().active, bb::ActionType::GETUP_FRONT);
}
