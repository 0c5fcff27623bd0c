// RobotModel and RobotBody on tiny inline URDFs: a model need not be a NAO
// to load and to be built in the (production) World; the NAO's libagent
// binding is checked apart (NaoBinding) and refuses them with the NAO's
// error. Units: m, kg, rad, rad/s; field frame (z up).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "sim/nao_model/NaoBinding.hpp"
#include "sim/nao_model/RobotBody.hpp"
#include "sim/world/World.hpp"

using namespace simswift;

namespace {

// An arm: a 1 kg, 0.5 m rod along +x from a hinge about +y (centre of mass
// 0.25 m out, I = m l^2 / 12 about it), on a pivot block. Turning +theta
// about y takes +x toward -z, so gravity drives theta up; the hinge allows
// [-1, 0] rad, i.e. from 57 deg raised to horizontal.
// Its velocity limit is tiny so that the limp joint's friction
// (ServoConfig::limp_damping x the limit) is 2e-4 N*m, nothing beside
// gravity's 2.5 N*m.
const char* kArmUrdf = R"(<robot name="arm">
  <link name="pivot">
    <inertial><mass value="1"/>
      <inertia ixx="1e-3" iyy="1e-3" izz="1e-3" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.04 0.04 0.04"/></geometry></collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="pivot"/><child link="bob"/>
    <origin xyz="0 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="0" velocity="0.01" effort="1"/>
  </joint>
  <link name="bob">
    <inertial><origin xyz="0.25 0 0"/><mass value="1"/>
      <inertia ixx="1e-4" iyy="0.02083" izz="0.02083" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0.5 0 0"/><geometry><sphere radius="0.02"/></geometry></collision>
  </link>
</robot>)";

}  // namespace

TEST(TinyModels, AnyUrdfLoadsWithoutTheNaoJoints) {
  const RobotModel m = RobotModel::loadUrdfString(kArmUrdf, "arm.urdf");
  ASSERT_EQ(m.links().size(), 2u);
  ASSERT_EQ(m.joints().size(), 1u);
  EXPECT_EQ(m.links()[m.rootLink()].name, "pivot");
  const JointSpec& j = m.joints()[0];
  EXPECT_EQ(j.name, "shoulder");
  EXPECT_EQ(m.links()[j.child_link].name, "bob");
  EXPECT_NEAR((j.axis - Eigen::Vector3d::UnitY()).norm(), 0, 1e-12);
  EXPECT_DOUBLE_EQ(j.lower, -1.0);
  EXPECT_DOUBLE_EQ(j.upper, 0.0);
  EXPECT_DOUBLE_EQ(m.totalMass(), 2.0);
  EXPECT_EQ(m.source(), "arm.urdf");
}

// The NAO binding refuses it as it refuses a NAO URDF missing a joint:
// "file:line: missing joint '<name>' (a libagent joint)", at the <robot>.
TEST(TinyModels, NaoBindingRefusesANonNaoWithTheMissingJoint) {
  const RobotModel m = RobotModel::loadUrdfString(kArmUrdf, "arm.urdf");
  try {
    NaoBinding nao(m);
    FAIL() << "a one-hinge arm bound as a NAO";
  } catch (const ModelError& e) {
    EXPECT_STREQ(e.what(), "arm.urdf:1: missing joint 'HeadYaw' (a libagent joint)");
  }
}

// Built in the World, the arm's link frames follow the hinge angle.
TEST(TinyModels, RobotBodyPlacesTheLinksAtThePosture) {
  World w(FieldConfig::spl2017());
  w.removeBall();
  const auto model = std::make_shared<const RobotModel>(RobotModel::loadUrdfString(kArmUrdf, "arm.urdf"));
  const int i = w.addRobot(model, 0.0, 0.0, 0.0, {-0.5});
  const RobotBody& r = w.robot(i);
  EXPECT_NEAR(r.jointAngle(0), -0.5, 1e-9);
  const Eigen::Isometry3d pivot = r.linkPose(0), bob = r.linkPose(1);
  const Eigen::Vector3d tip = bob * Eigen::Vector3d(0.5, 0, 0) - pivot.translation();
  // -0.5 rad about y raises +x: (0.5 cos 0.5, 0, 0.5 sin 0.5) m from the pivot.
  EXPECT_NEAR((tip - Eigen::Vector3d(0.5 * std::cos(0.5), 0, 0.5 * std::sin(0.5))).norm(), 0, 1e-9);
}

// Released limp from 0.5 rad above horizontal, the arm falls onto its upper
// limit and stays on the hinge's mechanical stop, kStopBeyondLimit (0.01
// rad) past the limit. ODE enforces a stop from the substep after the angle
// passes it, so the arm may overrun by one substep's travel at its arrival
// speed. On the stop, gravity's 2.5 N*m presses it: the exact solver
// (WorldConfig::Solver::Exact) holds it there to 1e-5 rad, QuickStep's 20
// iterations leave it rattling (measured over the third second: within
// 2.7 mrad, mean 0.9 mrad off); 5 mrad for any tick and 2 mrad for the
// mean, where a stop that does not hold lets the arm hang 1.57 rad down.
// (With all the arm's mass in a bob at its tip, QuickStep rattles it
// +-15 mrad at up to 3 rad/s: the long lever's rows converge slowly.)
TEST(TinyModels, HingeAtItsLimitStopsThere) {
  World w(FieldConfig::spl2017());
  w.removeBall();
  const auto model = std::make_shared<const RobotModel>(RobotModel::loadUrdfString(kArmUrdf, "arm.urdf"));
  const int i = w.addRobot(model, 0.0, 0.0, 0.0, {-0.5});
  // The pivot held 1 m up by a fixed joint to the world (a test rig).
  Eigen::Isometry3d up = Eigen::Isometry3d::Identity();
  up.translation().z() = 1.0;
  w.robot(i).teleport(up);
  dJointID fixed = dJointCreateFixed(w.odeWorld(), nullptr);
  dJointAttach(fixed, w.robot(i).torsoBody(), nullptr);
  dJointSetFixed(fixed);

  const RobotBody& r = w.robot(i);
  const double stop = model->joints()[0].upper + RobotBody::kStopBeyondLimit;  // rad
  const double h = kTickSeconds / WorldConfig{}.substepsPerTick();  // s, one substep
  double highest = -10, fastest = 0;
  for (int k = 0; k < 200; ++k) {  // 2 s: it arrives after 0.2 s and settles
    w.step();
    highest = std::max(highest, r.jointAngle(0));
    fastest = std::max(fastest, std::fabs(r.jointVelocity(0)));
  }
  EXPECT_GT(fastest, 4.0);  // rad/s: it really fell onto the stop (5.2 rad/s)
  EXPECT_LT(highest, stop + fastest * h);
  double mean = 0, worst = 0;  // rad, over the next second, from the stop
  for (int k = 0; k < 100; ++k) {
    w.step();
    mean += (r.jointAngle(0) - stop) / 100;
    worst = std::max(worst, std::fabs(r.jointAngle(0) - stop));
  }
  std::printf("[tiny] arm on its stop: mean %.2f mrad, worst %.2f mrad from it\n", mean * 1e3, worst * 1e3);
  EXPECT_LT(std::fabs(mean), 2e-3);
  EXPECT_LT(worst, 5e-3);
  EXPECT_TRUE(w.takeEvents().empty());
}
