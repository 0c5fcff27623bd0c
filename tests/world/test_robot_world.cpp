// Robots in the world: standing, contacts, blow-up recovery, determinism,
// ray casts that ignore the caster.
#include <gtest/gtest.h>

#include <cmath>

#include "agent/program/Postures.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/runner/FallDetector.hpp"
#include "sim/world/World.hpp"
#include "tests/support/NaoV5Model.hpp"

using namespace simswift;

namespace {

using simswift::testing::naoV5Model;

// The robot program's standing posture (agent/program/Postures.hpp), model joint order.
std::vector<double> standingPosture(const RobotModel& m) {
  return simswift::NaoBinding(m).posture(agent::program::postureAngles(agent::program::Posture::Stand));
}

int addStandingRobot(World& w, double x, double y, double theta) {
  auto model = naoV5Model();
  const auto q = standingPosture(*model);
  const int i = w.addRobot(model, x, y, theta, q);
  w.robot(i).holdPosture(q);
  return i;
}

double torsoZ(const World& w, int i) {
  return w.robot(i).linkPose(w.robot(i).model().rootLink()).translation().z();
}

}  // namespace

TEST(RobotWorld, PlacedWithFeetOnTheCarpet) {
  World w(FieldConfig::spl2017());
  const int i = addStandingRobot(w, -1.0, 0.5, 0.3);
  EXPECT_NEAR(w.robot(i).lowestPoint(), 0.0, 1e-9);
  const Eigen::Vector3d t = w.robot(i).linkPose(w.robot(i).model().rootLink()).translation();
  EXPECT_NEAR(t.x(), -1.0, 0.05);  // torso above its feet
  EXPECT_NEAR(t.y(), 0.5, 0.05);
  EXPECT_GT(t.z(), runner::FallDetector::kStandHeight);  // up, as the fall detector counts it
}

TEST(RobotWorld, StandingRobotStaysUpFor10s) {
  World w(FieldConfig::spl2017());
  w.placeBall(2.0, 2.0);  // not under the feet
  const int i = addStandingRobot(w, 0.0, 0.0, 0.0);
  for (int k = 0; k < 50; ++k) w.step();  // 0.5 s: settle into the contact layer
  const double z0 = torsoZ(w, i);
  double zmin = z0, zmax = z0;
  for (int k = 0; k < 1000; ++k) {  // 10 s
    w.step();
    zmin = std::min(zmin, torsoZ(w, i));
    zmax = std::max(zmax, torsoZ(w, i));
  }
  EXPECT_LT(zmax - zmin, 0.005) << "torso height range " << zmin << " .. " << zmax << " m";
  EXPECT_TRUE(w.takeEvents().empty());
  // Upright: torso z axis within 5 deg of vertical.
  const Eigen::Vector3d up = w.robot(i).linkPose(w.robot(i).model().rootLink()).linear().col(2);
  EXPECT_GT(up.z(), std::cos(5.0 * M_PI / 180));
}

TEST(RobotWorld, FootContactsCarryTheWeight) {
  World w(FieldConfig::spl2017());
  const int i = addStandingRobot(w, 1.0, 1.0, 0.0);
  for (int k = 0; k < 100; ++k) w.step();
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const LinkContact& c : w.contacts()) {
    EXPECT_EQ(c.robot, i);
    EXPECT_EQ(c.other, GeomTag::Ground);
    EXPECT_NEAR(c.position.z(), 0.0, 0.003);
    total += c.force;
  }
  const double weight = naoV5Model()->totalMass() * 9.81;
  EXPECT_NEAR(total.z(), weight, 0.05 * weight);
  EXPECT_LT(std::hypot(total.x(), total.y()), 0.05 * weight);
}

TEST(RobotWorld, BlowUpIsDetectedResetAndReported) {
  World w(FieldConfig::spl2017());
  w.placeBall(-2.0, 2.0);
  addStandingRobot(w, 0.0, 0.0, 0.0);
  const int i = addStandingRobot(w, 2.0, -1.0, M_PI / 2);
  for (int k = 0; k < 20; ++k) w.step();
  ASSERT_TRUE(w.takeEvents().empty());
  const Eigen::Vector3d placed = w.robot(i).linkPose(w.robot(i).model().rootLink()).translation();
  dBodySetLinearVel(w.robot(i).torsoBody(), 1e6, 0, 0);
  w.step();
  auto ev = w.takeEvents();
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].kind, WorldEvent::Kind::BlowUp);
  EXPECT_EQ(ev[0].robot, i);
  EXPECT_NE(ev[0].message.find("robot 1"), std::string::npos) << ev[0].message;
  // Back where it was placed, at rest, and it keeps standing.
  const Eigen::Vector3d now = w.robot(i).linkPose(w.robot(i).model().rootLink()).translation();
  EXPECT_LT((now - placed).norm(), 0.01);
  EXPECT_FALSE(w.robot(i).blownUp(1.0, 5.0));
  for (int k = 0; k < 100; ++k) w.step();
  EXPECT_TRUE(w.takeEvents().empty());
  EXPECT_GT(torsoZ(w, i), runner::FallDetector::kStandHeight);
}

TEST(RobotWorld, SameScenarioSameHash) {
  auto run = [](double ball_x) {
    World w(FieldConfig::spl2017());
    addStandingRobot(w, 0.0, 0.0, 0.0);
    addStandingRobot(w, 0.5, 0.0, M_PI);  // face to face: robot-robot contacts possible
    w.placeBall(ball_x, 0.0);
    w.setBallVelocity({-1.0, 0.0, 0.0});  // rolls into robot 0's feet... or past them
    for (int k = 0; k < 150; ++k) w.step();
    return w.stateHash();
  };
  const uint64_t a = run(1.5), b = run(1.5), c = run(1.6);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

TEST(RobotWorld, RayCastIgnoresOwnLinksButSeesOthers) {
  World w(FieldConfig::spl2017());
  const int a = addStandingRobot(w, 0.0, 0.0, 0.0);
  const int b = addStandingRobot(w, 1.0, 0.0, M_PI);
  const double h = torsoZ(w, a);
  // From inside robot a's torso, forward along +x at torso height.
  const double own_ignored = w.rayCast({0.0, 0.0, h}, {1, 0, 0}, 3.0, a);
  EXPECT_GT(own_ignored, 0.8);   // hits robot b's front, about 1 m away
  EXPECT_LT(own_ignored, 1.0);
  const double own_seen = w.rayCast({0.0, 0.0, h}, {1, 0, 0}, 3.0, -1);
  EXPECT_GE(own_seen, 0.0);
  EXPECT_LT(own_seen, 0.2);      // its own torso is in the way
  (void)b;
}

TEST(RobotWorld, InterleavedWorldsMatchASoloWorld) {
  // ODE's solver shares one random generator per process; stepping two
  // worlds alternately must not change either one's result.
  auto setup = [](World& w) {
    w.placeBall(1.0, 0.0);
    w.setBallVelocity({-1.0, 0.2, 0.0});
    addStandingRobot(w, 0.0, 0.0, 0.0);
  };
  World solo(FieldConfig::spl2017()), a(FieldConfig::spl2017()), b(FieldConfig::spl2017());
  setup(solo);
  setup(a);
  setup(b);
  b.setBallVelocity({-0.5, 0.0, 0.0});  // b differs, so its shuffles differ
  for (int k = 0; k < 100; ++k) {
    solo.step();
    a.step();
    b.step();
    b.step();
  }
  EXPECT_EQ(solo.stateHash(), a.stateHash());
}
