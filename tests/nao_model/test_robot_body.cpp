// RobotBody in the production World (sim/world/World.hpp with the default
// WorldConfig: QuickStep, 2 substeps of 5 ms per 10 ms tick, the sole
// patches and the joint projection): kinematics, servo speed limits,
// settling, joint stops and the shared hip motor.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include "common/libagent/AgentShared.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/nao_model/RobotBody.hpp"
#include "sim/world/World.hpp"
#include "tests/support/NaoV5Model.hpp"

using simswift::GeomTag;
using simswift::NaoBinding;
using simswift::RobotModel;
using simswift::RobotBody;

namespace {

constexpr double kDt = simswift::kTickSeconds;  // s, one World::step (a tick)
// s, one physics substep of the production World (5 ms)
const double kSubstep = simswift::kTickSeconds / simswift::WorldConfig{}.substepsPerTick();
const double kDeg = M_PI / 180.0;

using simswift::testing::naoV5Model;
const RobotModel& model() { return *naoV5Model(); }
const NaoBinding& nao() {
  static const NaoBinding b(model());
  return b;
}

// One NAO in the zero posture (clamped to the limits) standing on the
// carpet at the centre spot of the production World, no ball. fix_torso:
// hung 0.3 m higher, the torso held by a fixed joint to the world.
class Sim {
 public:
  explicit Sim(bool fix_torso = false) : world_(simswift::FieldConfig::spl2017()) {
    world_.removeBall();  // the robot stands on the centre spot
    world_.addRobot(naoV5Model(), 0, 0, 0, std::vector<double>(model().joints().size(), 0.0));
    if (fix_torso) {
      Eigen::Isometry3d torso = robot().linkPose(model().rootLink());
      torso.translation().z() += 0.3;  // hanging in the air
      robot().teleport(torso);
      // A test rig, not part of the World's API: ODE holds the torso.
      dJointID fixed = dJointCreateFixed(world_.odeWorld(), nullptr);
      dJointAttach(fixed, robot().torsoBody(), nullptr);
      dJointSetFixed(fixed);
    }
  }

  RobotBody& robot() { return world_.robot(0); }
  simswift::World& world() { return world_; }

  // All 25 libagent joints held at `angles` with stiffness `stiffness`.
  void command(const std::array<float, 25>& angles, float stiffness = 1.0f) {
    std::array<float, 25> s;
    s.fill(stiffness);
    nao().command(robot(), angles, s);
  }

  void step() { world_.step(); }  // one 10 ms tick

 private:
  simswift::World world_;
};

int joint(const char* name) { return model().jointIndex(name); }

// The posture nearest all-zero that is within every limit (the elbow rolls
// cannot reach 0), in libagent slots: commanding it counts no clamps.
std::array<float, 25> neutral() {
  std::array<float, 25> a;
  for (int i = 0; i < 25; ++i) {
    const auto& j = model().joints()[nao().joint(i)];
    a[i] = static_cast<float>(std::clamp(0.0, j.lower, j.upper));
  }
  return a;
}

}  // namespace

TEST(RobotBody, ZeroPostureKinematics) {
  Sim sim;
  RobotBody& r = sim.robot();
  const Eigen::Isometry3d torso = r.linkPose(model().rootLink());
  const Eigen::Isometry3d foot = r.linkPose(model().linkIndex("LFoot"));
  const Eigen::Vector3d rel = torso.inverse() * foot.translation();
  EXPECT_NEAR((rel - Eigen::Vector3d(0, 0.050, -0.085 - 0.100 - 0.1029)).norm(), 0, 1e-9);
  // The soles are the lowest geoms: 45.19 mm under the ankle.
  EXPECT_NEAR(foot.translation().z() - r.lowestPoint(), 0.04519, 1e-6);
  for (size_t j = 0; j < model().joints().size(); ++j) {
    const auto& spec = model().joints()[j];
    EXPECT_NEAR(r.jointAngle(j), std::clamp(0.0, spec.lower, spec.upper), 1e-9) << spec.name;
  }
  // Every geom tagged with its robot and link.
  ASSERT_FALSE(r.geoms().empty());
  for (dGeomID g : r.geoms()) {
    const auto* t = static_cast<const GeomTag*>(dGeomGetData(g));
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->kind, GeomTag::RobotLink);
    EXPECT_EQ(t->robot, 0);
    EXPECT_GE(t->link, 0);
  }
}

TEST(RobotBody, SetPostureReportsNaoAngles) {
  Sim sim;
  RobotBody& r = sim.robot();
  std::vector<double> posture(model().joints().size(), 0.0);
  posture[joint("HeadYaw")] = 0.5;
  posture[joint("LKneePitch")] = 1.0;
  posture[joint("LHipYawPitch")] = -0.3;
  posture[joint("LShoulderRoll")] = 5.0;  // beyond the 76 deg limit: clamped
  r.setPosture(posture);
  EXPECT_NEAR(r.jointAngle(joint("HeadYaw")), 0.5, 1e-9);
  EXPECT_NEAR(r.jointAngle(joint("LKneePitch")), 1.0, 1e-9);
  EXPECT_NEAR(r.jointAngle(joint("LShoulderRoll")), 76 * kDeg, 1e-6);
  EXPECT_NEAR(r.jointAngle(joint("RHipYawPitch")), -0.3, 1e-9);  // mimic
  // Positive HeadYaw turns the head to the left (about +z).
  const Eigen::Matrix3d rel = r.linkPose(model().rootLink()).linear().transpose() *
                              r.linkPose(model().linkIndex("Head")).linear();
  EXPECT_NEAR(std::atan2(rel(1, 0), rel(0, 0)), 0.5, 1e-9);
}

TEST(RobotBody, StandsStillWhenStiff) {
  Sim sim;
  RobotBody& r = sim.robot();
  sim.command(neutral());
  const double z0 = r.linkPose(model().rootLink()).translation().z();
  for (int i = 0; i < 200; ++i) sim.step();  // 2 s
  EXPECT_FALSE(r.blownUp(50, 200));
  const Eigen::Isometry3d torso = r.linkPose(model().rootLink());
  EXPECT_NEAR(torso.translation().z(), z0, 0.01);            // m
  EXPECT_GT(torso.linear()(2, 2), std::cos(5 * kDeg));       // upright within 5 deg
  EXPECT_LT(r.linkLinearVelocity(model().rootLink(), Eigen::Vector3d::Zero()).norm(), 0.01);
}

TEST(RobotBody, StepTargetRespectsMaxSpeedAndSettles) {
  Sim sim;
  RobotBody& r = sim.robot();
  auto cmd = neutral();
  sim.command(cmd);
  for (int i = 0; i < 20; ++i) sim.step();  // 0.2 s
  struct Case { const char* name; int slot; double target; };
  const Case cases[] = {{"HeadYaw", 0, 1.5}, {"LShoulderPitch", 2, -1.2}, {"RElbowYaw", 21, 1.0}};
  for (const Case& c : cases) cmd[c.slot] = static_cast<float>(c.target);
  sim.command(cmd);
  double max_speed[3] = {0, 0, 0};
  double prev[3];
  for (int k = 0; k < 3; ++k) prev[k] = r.jointAngle(joint(cases[k].name));
  for (int i = 0; i < 100; ++i) {  // 1 s
    sim.step();
    for (int k = 0; k < 3; ++k) {
      const double a = r.jointAngle(joint(cases[k].name));
      max_speed[k] = std::max(max_speed[k], std::abs(a - prev[k]) / kDt);
      prev[k] = a;
    }
  }
  for (int k = 0; k < 3; ++k) {
    const auto& spec = model().joints()[joint(cases[k].name)];
    SCOPED_TRACE(cases[k].name);
    // The no-load speed is the motor's ceiling: the arm joints move together
    // and carry their links' weight, so a tick may be pushed a little past
    // it (the motor then brakes) or stay well below it (torque-speed line).
    // Speeds are means over a tick (two substeps).
    EXPECT_LE(max_speed[k], spec.max_velocity * 1.1);  // rad/s
    // HeadYaw turns about the vertical, unloaded: close to no-load speed.
    EXPECT_GT(max_speed[k], spec.max_velocity * (k == 0 ? 0.9 : 0.7));
    EXPECT_NEAR(r.jointAngle(joint(cases[k].name)), cases[k].target, 1 * kDeg);
    std::cout << "  " << cases[k].name << ": peak " << max_speed[k] << " rad/s (max "
              << spec.max_velocity << "), final error "
              << (r.jointAngle(joint(cases[k].name)) - cases[k].target) / kDeg << " deg\n";
  }
}

TEST(RobotBody, StopsAtLimitWhenCommandedPast) {
  Sim sim;
  RobotBody& r = sim.robot();
  auto cmd = neutral();
  cmd[0] = 3.0f;  // HeadYaw beyond its 119.5 deg limit
  sim.command(cmd);
  const double upper = model().joints()[joint("HeadYaw")].upper;
  double highest = -10;
  for (int i = 0; i < 100; ++i) {  // 1 s
    sim.step();
    highest = std::max(highest, r.jointAngle(joint("HeadYaw")));
  }
  EXPECT_EQ(r.commandStats().clamped_angles, 1);
  // Arriving at full speed it may run onto the mechanical stop, just
  // outside the limit (RobotBody::kStopBeyondLimit), not past it.
  EXPECT_LT(highest, upper + RobotBody::kStopBeyondLimit + 1 * kDeg);
  // Settles at the limit within 2 deg (the motor board's position loop is
  // proportional only: torque = kp * error * stall / no-load speed).
  EXPECT_NEAR(r.jointAngle(joint("HeadYaw")), upper, 2 * kDeg);
}

TEST(RobotBody, HingeStopHoldsALimpJointAgainstTorque) {
  Sim sim(/*fix_torso=*/true);
  RobotBody& r = sim.robot();
  sim.command(neutral(), 0.0f);  // limp
  const int head = model().linkIndex("Head");
  const Eigen::Vector3d up = r.linkPose(model().rootLink()).linear().col(2);
  double highest = -10, peak = 0;
  // 0.3 N*m yawing left, as a tick's mean: ODE clears a body's added torque
  // after each substep, so the tick's angular impulse (0.3 N*m x 10 ms) goes
  // in during its first substep, as World::applyImpulse delivers a push.
  const double torque = 0.3 * simswift::WorldConfig{}.substepsPerTick();  // N*m in the first substep
  for (int i = 0; i < 100; ++i) {  // 1 s
    dBodyAddTorque(r.body(head), torque * up.x(), torque * up.y(), torque * up.z());
    sim.step();
    highest = std::max(highest, r.jointAngle(joint("HeadYaw")));
    peak = std::max(peak, std::abs(r.jointVelocity(joint("HeadYaw"))));
  }
  // The mechanical stop, a little outside the commanded range.
  const double stop = model().joints()[joint("HeadYaw")].upper + RobotBody::kStopBeyondLimit;
  // ODE enforces a stop once the angle is past it, so a fast joint may
  // overrun by up to one substep's travel before being pushed back.
  EXPECT_LT(highest, stop + peak * kSubstep + 1 * kDeg);
  EXPECT_NEAR(r.jointAngle(joint("HeadYaw")), stop, 0.1 * kDeg);
}

TEST(RobotBody, LHipYawPitchDrivesBothHips) {
  Sim sim(/*fix_torso=*/true);
  RobotBody& r = sim.robot();
  auto cmd = neutral();
  cmd[common::libagent::Joints::LHipYawPitch] = -0.5f;
  sim.command(cmd);
  double worst = 0;
  for (int i = 0; i < 100; ++i) {  // 1 s
    sim.step();
    worst = std::max(worst, std::abs(r.jointAngle(joint("LHipYawPitch")) -
                                     r.jointAngle(joint("RHipYawPitch"))));
  }
  EXPECT_NEAR(r.jointAngle(joint("LHipYawPitch")), -0.5, 1 * kDeg);
  EXPECT_NEAR(r.jointAngle(joint("RHipYawPitch")), -0.5, 1 * kDeg);
  EXPECT_LT(worst, 1 * kDeg);
}

// Measured with ODE 0.16: QuickStep (20 iterations) at 5 ms blows the bare NAO
// up; with the default inertia floor (ServoConfig::min_link_inertia) it
// stands. Probe on this model: floor 0 blows up at 5 and 10 ms; 5e-4 kg*m^2
// stands at both (torso sags 3 mm at 5 ms, 11 mm at 10 ms). The production
// World is that QuickStep (WorldConfig: 20 iterations, 5 ms substeps).
TEST(RobotBody, StandsWithQuickStepThanksToInertiaFloor) {
  ASSERT_EQ(simswift::WorldConfig{}.solver, simswift::WorldConfig::Solver::Quick);
  ASSERT_EQ(simswift::WorldConfig{}.quick_iterations, 20);
  Sim sim;
  RobotBody& r = sim.robot();
  sim.command(neutral());
  const double z0 = r.linkPose(model().rootLink()).translation().z();
  for (int i = 0; i < 200; ++i) {  // 2 s
    sim.step();
    ASSERT_FALSE(r.blownUp(50, 200)) << "tick " << i;
  }
  // The World resets a robot that blew up (and says so): none did.
  EXPECT_TRUE(sim.world().takeEvents().empty());
  const Eigen::Isometry3d torso = r.linkPose(model().rootLink());
  EXPECT_NEAR(torso.translation().z(), z0, 0.01);       // m
  EXPECT_GT(torso.linear()(2, 2), std::cos(5 * kDeg));  // upright within 5 deg
}

// Holding the arm straight forward, the shoulder motor carries the arm's
// weight: torque = -(sum of m * g * horizontal CoM distance) about +y.
TEST(RobotBody, JointTorqueBalancesGravity) {
  Sim sim(/*fix_torso=*/true);
  RobotBody& r = sim.robot();
  sim.command(neutral());
  for (int i = 0; i < 100; ++i) sim.step();  // 1 s to settle
  const int sp = joint("LShoulderPitch");
  const Eigen::Vector3d shoulder =
      r.linkPose(model().joints()[sp].child_link).translation();  // hinge anchor (m)
  double moment = 0;  // N*m about +y through the shoulder
  const char* arm[] = {"LShoulder", "LBicep", "LElbow", "LForeArm", "LWrist", "LFinger"};
  for (const char* name : arm) {
    const int l = model().linkIndex(name);
    const Eigen::Vector3d com = r.linkPose(l) * model().links()[l].inertial_origin.xyz;
    moment += model().links()[l].mass * 9.81 * (com.x() - shoulder.x());
  }
  EXPECT_GT(moment, 0.3);  // the arm's weight is well forward of the shoulder
  EXPECT_NEAR(r.jointTorque(sp), -moment, 0.05 * moment);
  // The position loop is proportional (Servo.hpp): holding torque tau needs
  // an error of tau * compliance / kp, i.e. the arm sags that much.
  const auto& servo = r.servos();
  const double compliance = servo.config().torque_speed_line
                                ? servo.limits(sp).max_velocity /
                                      (servo.config().gear_efficiency * servo.limits(sp).max_effort)
                                : 0.0;  // the hard velocity motor: no sag
  const double sag = moment * compliance / servo.config().kp;  // rad, downward = +pitch
  EXPECT_NEAR(r.jointAngle(sp), sag, 0.2 * sag + 1 * kDeg);
}
