// RobotModel: the shipped URDF loads as a complete NAO, and malformed URDFs are
// rejected with errors naming the file and the offending link or joint.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "common/libagent/AgentShared.hpp"
#include "sim/nao_model/Motors.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/nao_model/RobotModel.hpp"
#include "tests/support/NaoV5Model.hpp"

using simswift::ModelError;
using simswift::RobotModel;

namespace {

using simswift::testing::kNaoV5UrdfPath;
using simswift::testing::readNaoV5Urdf;

// Returns the text of the first <tag name="name"> ... </tag> element.
std::pair<size_t, size_t> element(const std::string& xml, const std::string& tag, const std::string& name) {
  const size_t b = xml.find("<" + tag + " name=\"" + name + "\"");
  EXPECT_NE(b, std::string::npos) << tag << " " << name;
  const size_t e = xml.find("</" + tag + ">", b) + tag.size() + 3;
  return {b, e};
}

// Runs the loader on `xml` and returns the ModelError message ("" if none).
std::string errorOf(const std::string& xml) {
  try {
    // The model, then its libagent joints, as the runner checks them.
    const RobotModel m = RobotModel::loadUrdfString(xml, "bad.urdf");
    const simswift::NaoBinding nao(m);
  } catch (const ModelError& e) {
    std::cout << "  ModelError: " << e.what() << "\n";
    return e.what();
  }
  return "";
}

double deg(double d) { return d * M_PI / 180.0; }

}  // namespace

TEST(RobotModel, LoadsTheNaoV5) {
  const RobotModel m = RobotModel::loadUrdf(kNaoV5UrdfPath);
  EXPECT_EQ(m.joints().size(), 26u);
  EXPECT_EQ(m.links().size(), 27u);  // 26 joint children + torso
  EXPECT_EQ(m.links()[m.rootLink()].name, "torso");
  // Published total 5.3 kg; other documents give 5.18 and 5.48.
  EXPECT_GT(m.totalMass(), 5.18);
  EXPECT_LT(m.totalMass(), 5.48);
  EXPECT_NEAR(m.totalMass(), 5.305, 0.01);
  const simswift::NaoBinding nao(m);
  for (int i = 0; i < common::libagent::kNumJoints; ++i) {
    const int j = nao.joint(i);
    ASSERT_GE(j, 0);
    EXPECT_EQ(m.joints()[j].name, common::libagent::Joints::kNames[i]);
    EXPECT_EQ(nao.slot(j), i);
  }
  const int r = m.jointIndex("RHipYawPitch");
  ASSERT_GE(r, 0);
  EXPECT_EQ(nao.slot(r), -1);
  ASSERT_TRUE(m.joints()[r].mimic.has_value());
  EXPECT_EQ(*m.joints()[r].mimic, "LHipYawPitch");
  // Parents precede children, so forward kinematics is one pass.
  for (const auto& j : m.joints()) EXPECT_LT(j.parent_link, j.child_link) << j.name;
}

TEST(RobotModel, PublishedNumbers) {
  const RobotModel m = RobotModel::loadUrdf(kNaoV5UrdfPath);
  auto joint = [&](const char* n) -> const simswift::JointSpec& { return m.joints()[m.jointIndex(n)]; };
  auto link = [&](const char* n) -> const simswift::LinkSpec& { return m.links()[m.linkIndex(n)]; };
  EXPECT_NEAR(joint("HeadYaw").origin.xyz.z(), 0.1265, 1e-9);
  EXPECT_NEAR(joint("LShoulderPitch").origin.xyz.y(), 0.098, 1e-9);
  EXPECT_NEAR(joint("RHipYawPitch").origin.xyz.y(), -0.050, 1e-9);
  EXPECT_NEAR(joint("LHipYawPitch").axis.z(), -std::sqrt(0.5), 1e-5);
  EXPECT_NEAR(joint("RHipYawPitch").axis.z(), std::sqrt(0.5), 1e-5);
  EXPECT_NEAR(joint("LKneePitch").origin.xyz.z(), -0.100, 1e-9);
  EXPECT_NEAR(joint("LAnklePitch").origin.xyz.z(), -0.1029, 1e-9);
  // Right roll limits mirror the left.
  EXPECT_NEAR(joint("LShoulderRoll").upper, deg(76), 1e-5);
  EXPECT_NEAR(joint("RShoulderRoll").lower, -deg(76), 1e-5);
  EXPECT_NEAR(joint("RAnkleRoll").upper, deg(22.79), 1e-5);
  EXPECT_NEAR(joint("LHipPitch").max_velocity, 6.402, 1e-9);
  EXPECT_NEAR(link("LThigh").mass, 0.38968, 1e-9);
  EXPECT_NEAR(link("RThigh").inertial_origin.xyz.y(), -0.00221, 1e-9);
  // Sole bottom 45.19 mm below the ankle; cylinders collide as capsules.
  const auto& sole = link("LFoot").collisions.at(0);
  EXPECT_EQ(sole.type, simswift::ShapeType::Box);
  EXPECT_NEAR(sole.origin.xyz.z() - sole.size.z() / 2, -0.04519, 1e-9);
  EXPECT_NEAR(sole.size.x(), 0.160, 1e-9);
  EXPECT_EQ(link("LThigh").collisions.at(0).type, simswift::ShapeType::Capsule);
  EXPECT_EQ(link("LThigh").visuals.at(0).type, simswift::ShapeType::Cylinder);
}

TEST(RobotModel, MissingFileNamesThePath) {
  try {
    RobotModel::loadUrdf("/nonexistent/nao.urdf");
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/nao.urdf"), std::string::npos);
  }
}

TEST(RobotModel, LinkWithoutMassIsRejected) {
  std::string xml = readNaoV5Urdf();
  auto [b, e] = element(xml, "link", "LThigh");
  const size_t m = xml.find("<mass", b);
  ASSERT_LT(m, e);
  xml.replace(m, xml.find("/>", m) + 2 - m, "<mass value=\"0\"/>");
  const std::string err = errorOf(xml);
  EXPECT_NE(err.find("bad.urdf"), std::string::npos) << err;
  EXPECT_NE(err.find("LThigh"), std::string::npos) << err;
}

TEST(RobotModel, LinkWithoutMassElementIsRejected) {
  std::string xml = readNaoV5Urdf();
  auto [b, e] = element(xml, "link", "Head");
  const size_t m = xml.find("<mass", b);
  ASSERT_LT(m, e);
  xml.erase(m, xml.find("/>", m) + 2 - m);
  const std::string err = errorOf(xml);
  EXPECT_NE(err.find("bad.urdf"), std::string::npos) << err;
  EXPECT_NE(err.find("Head"), std::string::npos) << err;
}

TEST(RobotModel, LinkWithoutInertialIsRejected) {
  std::string xml = readNaoV5Urdf();
  auto [b, e] = element(xml, "link", "RTibia");
  const size_t ib = xml.find("<inertial>", b);
  const size_t ie = xml.find("</inertial>", ib) + 11;
  ASSERT_LT(ie, e);
  xml.erase(ib, ie - ib);
  const std::string err = errorOf(xml);
  EXPECT_NE(err.find("bad.urdf"), std::string::npos) << err;
  EXPECT_NE(err.find("RTibia"), std::string::npos) << err;
  EXPECT_NE(err.find("inertial"), std::string::npos) << err;
}

TEST(RobotModel, JointWithoutLimitsIsRejected) {
  std::string xml = readNaoV5Urdf();
  auto [b, e] = element(xml, "joint", "LKneePitch");
  const size_t l = xml.find("<limit", b);
  ASSERT_LT(l, e);
  xml.erase(l, xml.find("/>", l) + 2 - l);
  const std::string err = errorOf(xml);
  EXPECT_NE(err.find("bad.urdf"), std::string::npos) << err;
  EXPECT_NE(err.find("LKneePitch"), std::string::npos) << err;
}

TEST(RobotModel, InvertedLimitsAreRejected) {
  std::string xml = readNaoV5Urdf();
  auto [b, e] = element(xml, "joint", "HeadPitch");
  const size_t l = xml.find("lower=\"", b);
  ASSERT_LT(l, e);
  xml.replace(l, xml.find('"', l + 7) + 1 - l, "lower=\"1.0\"");
  const std::string err = errorOf(xml);
  EXPECT_NE(err.find("HeadPitch"), std::string::npos) << err;
  EXPECT_NE(err.find("lower"), std::string::npos) << err;
}

TEST(RobotModel, NonHingeJointIsRejected) {
  std::string xml = readNaoV5Urdf();
  auto [b, e] = element(xml, "joint", "RElbowYaw");
  const size_t t = xml.find("type=\"revolute\"", b);
  ASSERT_LT(t, e);
  xml.replace(t, 15, "type=\"fixed\"");
  const std::string err = errorOf(xml);
  EXPECT_NE(err.find("RElbowYaw"), std::string::npos) << err;
  EXPECT_NE(err.find("hinge"), std::string::npos) << err;
}

TEST(RobotModel, MissingLibagentJointIsRejected) {
  std::string xml = readNaoV5Urdf();
  const std::string from = "<joint name=\"LHipYawPitch\"";
  const size_t p = xml.find(from);
  ASSERT_NE(p, std::string::npos);
  xml.replace(p, from.size(), "<joint name=\"LHipYawPitchRenamed\"");
  const std::string err = errorOf(xml);
  EXPECT_NE(err.find("bad.urdf"), std::string::npos) << err;
  EXPECT_NE(err.find("missing joint 'LHipYawPitch'"), std::string::npos) << err;
}

TEST(RobotModel, MalformedXmlIsRejected) {
  const std::string xml = readNaoV5Urdf();
  const std::string err = errorOf(xml.substr(0, xml.size() / 2));
  EXPECT_NE(err.find("bad.urdf"), std::string::npos) << err;
  EXPECT_NE(err.find("parse"), std::string::npos) << err;
  EXPECT_NE(errorOf("this is not xml").find("bad.urdf"), std::string::npos);
}

TEST(RobotModel, PoseIsometry) {
  simswift::Pose3 p;
  p.xyz = Eigen::Vector3d(1, 2, 3);
  p.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  const Eigen::Vector3d q = p.isometry() * Eigen::Vector3d(1, 0, 0);
  EXPECT_NEAR((q - Eigen::Vector3d(1, 3, 3)).norm(), 0, 1e-12);
}

// The URDF's speed and effort limits are the motor table's joint-side
// no-load speed and stall torque (sim/nao_model/Motors.hpp, Aldebaran's NAO V5 (H25) documentation).
TEST(RobotModel, UrdfLimitsAgreeWithTheMotorTable) {
  const simswift::RobotModel m = simswift::RobotModel::loadUrdf(kNaoV5UrdfPath);
  int with_motor = 0;
  for (const auto& j : m.joints()) {
    const auto motor = simswift::naoJointMotor(j.name);
    if (!motor) continue;
    ++with_motor;
    EXPECT_NEAR(j.max_velocity, motor->noLoadSpeed(), 0.01 * j.max_velocity) << j.name;
    EXPECT_NEAR(j.max_effort, motor->stallTorque(), 0.03 * j.max_effort) << j.name;
  }
  EXPECT_EQ(with_motor, 22);  // all but the wrists and hands
  // Electrical figures from the 12 V winding: RE-Max 24 about 14.3 mN*m/A, 2.9 ohm.
  const auto knee = simswift::naoJointMotor("LKneePitch");
  ASSERT_TRUE(knee);
  EXPECT_NEAR(knee->motor.torqueConstant(), 0.0143, 0.0002);
  EXPECT_NEAR(knee->motor.resistance(), 2.88, 0.03);
}
