// agent/motion's leg kinematics against the simulated NAO model: the sole
// pose relative to the hip from Kinematics.hpp must match the URDF's link
// chain as ODE builds it, for random joint angles (mm, rad).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>

#include "agent/motion/JointLimits.hpp"
#include "agent/motion/Kinematics.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/world/World.hpp"

using namespace agent::motion;

TEST(MotionKinematics, ForwardKinematicsMatchesTheSimulatedModel) {
  auto model = std::make_shared<const simswift::RobotModel>(
      simswift::RobotModel::loadUrdf(SIMSWIFT_SOURCE_DIR "/models/nao_v5.urdf"));
  simswift::World w(simswift::FieldConfig::spl2017());
  std::vector<double> q(model->joints().size(), 0.0);
  const int robot = w.addRobot(model, 0, 0, 0, q);
  auto& body = w.robot(robot);
  const int torso = model->rootLink();
  const int lfoot = model->linkIndex("LFoot"), rfoot = model->linkIndex("RFoot");
  ASSERT_GE(lfoot, 0);
  ASSERT_GE(rfoot, 0);
  uint64_t x = 7;
  auto rnd = [&x](double lo, double hi) {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(x >> 11) / 9007199254740992.0;
  };
  for (int trial = 0; trial < 20; ++trial) {
    LegAngles l, r;
    l.hip_yaw_pitch = r.hip_yaw_pitch = rnd(-0.5, 0.3);
    l.hip_roll = rnd(-0.2, 0.3);
    r.hip_roll = rnd(-0.3, 0.2);
    l.hip_pitch = rnd(-0.8, 0.2);
    r.hip_pitch = rnd(-0.8, 0.2);
    l.knee = rnd(0, 1.5);
    r.knee = rnd(0, 1.5);
    l.ankle_pitch = rnd(-0.8, 0.5);
    r.ankle_pitch = rnd(-0.8, 0.5);
    l.ankle_roll = rnd(-0.2, 0.2);
    r.ankle_roll = rnd(-0.2, 0.2);
    const std::map<std::string, double> set = {
        {"LHipYawPitch", l.hip_yaw_pitch}, {"RHipYawPitch", r.hip_yaw_pitch}, {"LHipRoll", l.hip_roll},
        {"LHipPitch", l.hip_pitch},        {"LKneePitch", l.knee},            {"LAnklePitch", l.ankle_pitch},
        {"LAnkleRoll", l.ankle_roll},      {"RHipRoll", r.hip_roll},          {"RHipPitch", r.hip_pitch},
        {"RKneePitch", r.knee},            {"RAnklePitch", r.ankle_pitch},    {"RAnkleRoll", r.ankle_roll}};
    for (const auto& [name, a] : set) q[model->jointIndex(name)] = a;
    body.setPosture(q);
    const Eigen::Isometry3d t = body.linkPose(torso);
    for (int side = 0; side < 2; ++side) {
      const Eigen::Isometry3d f = t.inverse() * body.linkPose(side == 0 ? lfoot : rfoot);
      // Sole point: FootHeight below the foot link's origin (the ankle) in mm,
      // in the hip frame (torso shifted to the hip joint).
      const Eigen::Vector3d sole = f * Eigen::Vector3d(0, 0, -NaoDims::kFootHeight / 1000.0);
      const double hip_y = (side == 0 ? 1 : -1) * NaoDims::kHipOffsetY;
      const FootPose mine = legForward(side == 0 ? Leg::Left : Leg::Right, side == 0 ? l : r);
      EXPECT_NEAR(sole.x() * 1000, mine.position.x, 0.5) << "trial " << trial << " side " << side;
      EXPECT_NEAR(sole.y() * 1000 - hip_y, mine.position.y, 0.5) << "trial " << trial << " side " << side;
      EXPECT_NEAR(sole.z() * 1000 + NaoDims::kHipOffsetZ, mine.position.z, 0.5) << "trial " << trial;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(f.rotation()(i, j), mine.rotation.m[i][j], 1e-3);
    }
  }
}

// The clipper's limit table (agent/motion, from Aldebaran's NAO V5 (H25) documentation) agrees with the
// simulated model's joint limits and speeds, so clipped commands are never
// clamped again by the servo.
TEST(MotionKinematics, ClipperLimitsMatchTheModel) {
  const auto model = simswift::RobotModel::loadUrdf(SIMSWIFT_SOURCE_DIR "/models/nao_v5.urdf");
  const auto& lim = agent::motion::jointLimits();
  for (int i = 0; i < common::libagent::kNumJoints; ++i) {
    if (i == common::libagent::Joints::LHand || i == common::libagent::Joints::RHand) continue;  // fraction, not rad
    const auto& j = model.joints()[simswift::NaoBinding(model).joint(i)];
    EXPECT_NEAR(lim[i].lower, j.lower, 2e-3) << j.name;
    EXPECT_NEAR(lim[i].upper, j.upper, 2e-3) << j.name;
    EXPECT_NEAR(lim[i].max_velocity, j.max_velocity, 2e-3) << j.name;
  }
}
