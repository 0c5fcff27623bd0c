// The NAO hardware facts the robot code and the simulator share (common/nao/NaoFacts.hpp) held against
// the simulated body (models/nao_v5.urdf): the same joint limits and speeds,
// the same link offsets, FSRs on the soles, cameras on the head's face, and
// the leg kinematics reaching the URDF's sole.
#include <gtest/gtest.h>

#include <cmath>

#include "common/libagent/AgentShared.hpp"
#include "agent/motion/Kinematics.hpp"
#include "common/nao/NaoFacts.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/nao_model/RobotModel.hpp"

namespace nao = common::nao;
namespace J = common::libagent::Joints;
using simswift::RobotModel;

namespace {
const RobotModel& urdfModel() {
  static const RobotModel m = RobotModel::loadUrdf(std::string(SIMSWIFT_SOURCE_DIR) + "/models/nao_v5.urdf");
  return m;
}
// Joint origin (mm) in the parent link frame.
Eigen::Vector3d originMm(const std::string& joint) {
  const int j = urdfModel().jointIndex(joint);
  EXPECT_GE(j, 0) << joint;
  return urdfModel().joints()[j].origin.xyz * 1000.0;
}
const simswift::ShapeSpec& firstCollision(const std::string& link) {
  const int l = urdfModel().linkIndex(link);
  EXPECT_GE(l, 0) << link;
  return urdfModel().links()[l].collisions.at(0);
}
}  // namespace

TEST(NaoFacts, JointLimitsAndSpeedsMatchTheUrdf) {
  const auto& lim = nao::jointLimits();
  for (int i = 0; i < common::libagent::kNumJoints; ++i) {
    const int j = simswift::NaoBinding(urdfModel()).joint(i);
    ASSERT_GE(j, 0) << "libagent joint " << i;
    const auto& spec = urdfModel().joints()[j];
    // The URDF keeps 6 digits of the published degrees-derived radians.
    EXPECT_NEAR(lim[i].lower, spec.lower, 2e-5) << spec.name;
    EXPECT_NEAR(lim[i].upper, spec.upper, 2e-5) << spec.name;
    EXPECT_NEAR(lim[i].max_velocity, spec.max_velocity, 1e-4) << spec.name;
    EXPECT_LT(lim[i].lower, lim[i].upper) << spec.name;
  }
}

TEST(NaoFacts, LinkOffsetsMatchTheUrdf) {
  namespace L = nao::links;
  EXPECT_NEAR((originMm("HeadYaw") - Eigen::Vector3d(0, 0, L::kNeckOffsetZ)).norm(), 0, 1e-6);
  EXPECT_NEAR((originMm("LHipYawPitch") - Eigen::Vector3d(0, L::kHipOffsetY, -L::kHipOffsetZ)).norm(), 0, 1e-6);
  EXPECT_NEAR((originMm("RHipYawPitch") - Eigen::Vector3d(0, -L::kHipOffsetY, -L::kHipOffsetZ)).norm(), 0, 1e-6);
  EXPECT_NEAR((originMm("LKneePitch") - Eigen::Vector3d(0, 0, -L::kThighLength)).norm(), 0, 1e-6);
  EXPECT_NEAR((originMm("LAnklePitch") - Eigen::Vector3d(0, 0, -L::kTibiaLength)).norm(), 0, 1e-6);
  EXPECT_NEAR((originMm("LShoulderPitch") - Eigen::Vector3d(0, L::kShoulderOffsetY, L::kShoulderOffsetZ)).norm(), 0,
              1e-6);
  EXPECT_NEAR((originMm("LElbowYaw") - Eigen::Vector3d(L::kUpperArmLength, L::kElbowOffsetY, 0)).norm(), 0, 1e-6);
  EXPECT_NEAR(originMm("LWristYaw").x(), L::kLowerArmLength, 1e-6);
  // The sole: bottom of the foot's collision box.
  for (const char* foot : {"LFoot", "RFoot"}) {
    const auto& sole = firstCollision(foot);
    ASSERT_EQ(sole.type, simswift::ShapeType::Box);
    EXPECT_NEAR((sole.origin.xyz.z() - sole.size.z() / 2) * 1000.0, -L::kFootHeight, 1e-6) << foot;
  }
}

TEST(NaoFacts, FsrsLieOnTheirSoleAndMirror) {
  for (auto [side, link] : {std::pair{nao::Side::Left, "LFoot"}, std::pair{nao::Side::Right, "RFoot"}}) {
    const auto& sole = firstCollision(link);
    const Eigen::Vector3d c = sole.origin.xyz * 1000.0, half = sole.size * 500.0;
    for (int i = 0; i < 4; ++i) {
      const nao::Point2 p = nao::fsrPosition(side, static_cast<nao::Fsr>(i));
      EXPECT_LT(std::fabs(p.x - c.x()), half.x()) << link << " FSR " << i;
      EXPECT_LT(std::fabs(p.y - c.y()), half.y()) << link << " FSR " << i;
    }
  }
  // Names follow the foot: a "left" sensor is left of its "right" partner.
  for (nao::Side side : {nao::Side::Left, nao::Side::Right}) {
    EXPECT_GT(nao::fsrPosition(side, nao::Fsr::FrontLeft).y, nao::fsrPosition(side, nao::Fsr::FrontRight).y);
    EXPECT_GT(nao::fsrPosition(side, nao::Fsr::RearLeft).y, nao::fsrPosition(side, nao::Fsr::RearRight).y);
    EXPECT_GT(nao::fsrPosition(side, nao::Fsr::FrontLeft).x, nao::fsrPosition(side, nao::Fsr::RearLeft).x);
  }
  // Mirror image: the right foot's front-left is the left foot's front-right.
  EXPECT_EQ(nao::fsrPosition(nao::Side::Right, nao::Fsr::FrontLeft).y,
            -nao::fsrPosition(nao::Side::Left, nao::Fsr::FrontRight).y);
}

TEST(NaoFacts, CamerasSitOnTheFaceOfTheHead) {
  const auto& head = firstCollision("Head");
  ASSERT_EQ(head.type, simswift::ShapeType::Sphere);
  const Eigen::Vector3d centre = head.origin.xyz * 1000.0;
  const double r = head.radius * 1000.0;
  for (nao::Camera cam : {nao::Camera::Top, nao::Camera::Bottom}) {
    const nao::CameraMount& m = nao::cameraMount(cam);
    const double d = (Eigen::Vector3d(m.x, m.y, m.z) - centre).norm();
    // Inside the head's sphere, within 10 mm of its surface, in front.
    EXPECT_LT(d, r) << static_cast<int>(cam);
    EXPECT_GT(d, r - 10.0) << static_cast<int>(cam);
    EXPECT_GT(m.x, 0.0);
  }
  // The bottom camera looks further down than the top one and the two views
  // overlap only a little (the bottom's upper edge is above the top's lower edge).
  EXPECT_GT(nao::kBottomCamera.pitch_down, nao::kTopCamera.pitch_down);
  // The same with the V6's narrower lens (the same mounts).
  for (const nao::CameraLens& lens : {nao::kV5CameraLens, nao::kV6CameraLens})
    EXPECT_LT(nao::kBottomCamera.pitch_down - lens.vertical_fov / 2, nao::kTopCamera.pitch_down + lens.vertical_fov / 2);
}

TEST(NaoFacts, LegKinematicsReachTheUrdfSole) {
  // Zero angles: the URDF chain torso -> hip -> knee -> ankle -> sole.
  const Eigen::Vector3d hip = originMm("LHipYawPitch");
  const Eigen::Vector3d ankle = hip + originMm("LHipRoll") + originMm("LHipPitch") + originMm("LKneePitch") +
                                originMm("LAnklePitch") + originMm("LAnkleRoll");
  const auto& sole = firstCollision("LFoot");
  const double sole_z = ankle.z() + (sole.origin.xyz.z() - sole.size.z() / 2) * 1000.0;
  const agent::motion::FootPose f = agent::motion::legForward(agent::motion::Leg::Left, {});
  // legForward is in the hip frame; the URDF numbers are in the torso frame.
  EXPECT_NEAR(f.position.x, ankle.x() - hip.x(), 1e-6);
  EXPECT_NEAR(f.position.y, ankle.y() - hip.y(), 1e-6);
  EXPECT_NEAR(f.position.z, sole_z - hip.z(), 1e-6);
}
