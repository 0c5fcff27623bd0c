// A penalised robot is carried to the sideline and back (World level).
#include <gtest/gtest.h>

#include <cmath>

#include "agent/program/Postures.hpp"
#include "sim/game/Sideline.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/runner/FallDetector.hpp"

using namespace simswift;
using namespace simswift::game;

namespace {
std::shared_ptr<const RobotModel> naoModel() {
  static auto model = std::make_shared<const RobotModel>(RobotModel::loadUrdf(SIMSWIFT_SOURCE_DIR "/models/nao_v5.urdf"));
  return model;
}
std::vector<double> standing() {
  return simswift::NaoBinding(*naoModel()).posture(agent::program::postureAngles(agent::program::Posture::Stand));
}
int addStanding(World& w, double x, double y, double theta) {
  const int i = w.addRobot(naoModel(), x, y, theta, standing());
  w.robot(i).holdPosture(standing());
  return i;
}
double angleDiff(double a, double b) { return std::remainder(a - b, 2 * M_PI); }
}  // namespace

TEST(Sideline, PoseIsOnTheTouchLineLevelWithTheOwnPenaltyMark) {
  const FieldConfig f = FieldConfig::spl2017();  // 9 x 6 m
  PlanarPose p = sidelinePose(f, 0, 0.5);
  EXPECT_DOUBLE_EQ(p.x, -(4.5 - 1.3));
  EXPECT_DOUBLE_EQ(p.y, 3.0);
  EXPECT_NEAR(p.theta, -M_PI / 2, 1e-12);  // facing into the field
  p = sidelinePose(f, 1, -2.0);
  EXPECT_DOUBLE_EQ(p.x, 4.5 - 1.3);
  EXPECT_DOUBLE_EQ(p.y, -3.0);
  EXPECT_NEAR(p.theta, M_PI / 2, 1e-12);
  EXPECT_DOUBLE_EQ(sidelinePose(f, 0, 1.0, 2).x, -(3.2 - 2 * kSidelineSpacing));
}

// Tolerances: the torso sits within 5 cm of its feet's (x, y) when standing.
TEST(Sideline, PenalisedRobotGoesToTheSidelineAndBack) {
  World w(FieldConfig::spl2017());
  w.placeBall(2.0, -2.0);
  const int a = addStanding(w, 1.0, 0.5, 0.3);
  const int b = addStanding(w, -0.5, 1.5, 0.0);
  for (int k = 0; k < 50; ++k) w.step();
  PenaltyPlacer placer(standing());
  const PlanarPose before = robotPose(w, a);
  const PlanarPose at = placer.penalise(w, a, 0);
  EXPECT_TRUE(placer.holds(a));
  for (int k = 0; k < 100; ++k) w.step();  // 1 s standing on the sideline
  PlanarPose now = robotPose(w, a);
  EXPECT_NEAR(now.x, -3.2, 0.05);
  EXPECT_NEAR(now.y, 3.0, 0.05);
  EXPECT_NEAR(angleDiff(now.theta, -M_PI / 2), 0, 0.1);
  EXPECT_NEAR(at.x, -3.2, 1e-12);
  // A second penalised teammate on the same side waits one spacing along.
  const PlanarPose at_b = placer.penalise(w, b, 0);
  EXPECT_NEAR(at_b.x, -3.2 + kSidelineSpacing, 1e-12);
  EXPECT_NEAR(at_b.y, 3.0, 1e-12);
  // Unpenalised: back where it was taken from, standing.
  placer.unpenalise(w, a, /*restore=*/true);
  EXPECT_FALSE(placer.holds(a));
  for (int k = 0; k < 100; ++k) w.step();
  now = robotPose(w, a);
  EXPECT_NEAR(now.x, before.x, 0.05);
  EXPECT_NEAR(now.y, before.y, 0.05);
  EXPECT_NEAR(angleDiff(now.theta, before.theta), 0, 0.1);
  const double z = w.robot(a).linkPose(w.robot(a).model().rootLink()).translation().z();
  EXPECT_GT(z, runner::FallDetector::kStandHeight);  // standing, not fallen
  // Left on the sideline (SPL re-entry) when not restored.
  placer.unpenalise(w, b, /*restore=*/false);
  for (int k = 0; k < 20; ++k) w.step();
  EXPECT_NEAR(robotPose(w, b).y, 3.0, 0.05);
}
