// The ball on the field: rolling resistance, posts, nets, determinism.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/world/World.hpp"

using namespace simswift;

namespace {

FieldConfig splField() { return FieldConfig::loadYaml(SIMSWIFT_SOURCE_DIR "/fields/spl_2017.yaml"); }

void run(World& w, double seconds) {
  const int ticks = static_cast<int>(std::lround(seconds / kTickSeconds));
  for (int i = 0; i < ticks; ++i) w.step();
}

}  // namespace

TEST(Ball, RestsOnTheCarpet) {
  World w(splField());
  w.placeBall(1.0, -1.0);
  run(w, 1.0);
  Eigen::Vector3d p = w.ballPosition();
  EXPECT_NEAR(p.z(), 0.05, 0.002);  // radius, within the 1 mm contact layer
  EXPECT_NEAR(p.x(), 1.0, 1e-6);
  EXPECT_NEAR(p.y(), -1.0, 1e-6);
  EXPECT_LT(w.ballVelocity().norm(), 1e-3);
}

TEST(Ball, PushedAt2MpsRollsAFewMetresAndStops) {
  World w(splField());
  w.placeBall(-3.0, 0.0);
  w.setBallVelocity({2.0, 0, 0});
  double stop_time = -1;
  for (int i = 0; i < 1000; ++i) {  // 10 s
    w.step();
    if (stop_time < 0 && w.ballVelocity().norm() < 0.01) stop_time = w.time();
  }
  const double distance = w.ballPosition().x() + 3.0;
  EXPECT_GT(distance, 1.0);
  EXPECT_LT(distance, 6.0);
  EXPECT_NEAR(w.ballPosition().y(), 0.0, 1e-6);  // straight
  ASSERT_GT(stop_time, 0) << "still moving at " << w.ballVelocity().norm() << " m/s after 10 s";
  EXPECT_LT(stop_time, 10.0);
  EXPECT_LT(w.ballVelocity().norm(), 1e-3);
  std::printf("[ball] 2 m/s push: rolled %.2f m, stopped after %.2f s\n", distance, stop_time);
}

TEST(Ball, ReboundsOffAGoalPost) {
  FieldConfig f = splField();
  World w(f);
  const double post_y = f.goal.inner_width / 2 + f.goal.post_diameter / 2;  // 0.8 m
  // Roll along the goal-line direction (x) straight at the near post's centre.
  w.placeBall(f.length / 2 - 1.0, post_y);
  w.setBallVelocity({2.0, 0, 0});
  double max_vx = 0, min_vx = 0;
  for (int i = 0; i < 100; ++i) {  // 1 s
    w.step();
    max_vx = std::max(max_vx, w.ballVelocity().x());
    min_vx = std::min(min_vx, w.ballVelocity().x());
  }
  EXPECT_GT(max_vx, 1.0);
  EXPECT_LT(min_vx, -0.3) << "ball did not bounce back off the post";
  EXPECT_LT(w.ballPosition().x(), f.length / 2 - 0.1);  // in front of the post
}

TEST(Ball, StoppedByTheNet) {
  FieldConfig f = splField();
  World w(f);
  w.placeBall(f.length / 2 - 1.0, 0.2);
  w.setBallVelocity({3.0, 0, 0});
  double max_x = -1e9;
  for (int i = 0; i < 300; ++i) {  // 3 s
    w.step();
    max_x = std::max(max_x, w.ballPosition().x());
  }
  const double r = f.ball.diameter / 2;
  const Eigen::Vector3d p = w.ballPosition();
  EXPECT_GT(max_x, f.length / 2 + r) << "ball never entered the goal";
  EXPECT_LT(max_x, f.length / 2 + f.goal.depth + 0.01) << "ball went through the net";
  // It stays inside: behind the goal line, not bounced out onto the field.
  EXPECT_GT(p.x(), f.length / 2);
  EXPECT_LT(p.x(), f.length / 2 + f.goal.depth);
  EXPECT_LT(w.ballVelocity().norm(), 0.05);
}

TEST(Ball, SameRunSameHashDifferentPlacementDifferentHash) {
  auto hashAfter = [](double bx) {
    World w(FieldConfig::spl2017());
    w.placeBall(bx, 0.3);
    w.setBallVelocity({1.5, -0.5, 0});
    run(w, 1.0);
    return w.stateHash();
  };
  const uint64_t a = hashAfter(0.0), b = hashAfter(0.0), c = hashAfter(0.001);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

TEST(Ball, RayCastHitsGroundAndPost) {
  FieldConfig f = splField();
  World w(f);
  w.placeBall(-2, -2);
  EXPECT_NEAR(w.rayCast({0, 0, 1.0}, {0, 0, -1}, 5.0, -1), 1.0, 1e-9);
  // Toward the far post from 1 m in front of it, 0.3 m up: hits its face.
  const double post_y = f.goal.inner_width / 2 + f.goal.post_diameter / 2;
  EXPECT_NEAR(w.rayCast({f.length / 2 - 1.0, post_y, 0.3}, {1, 0, 0}, 5.0, -1),
              1.0 - f.goal.post_diameter / 2, 1e-6);
  EXPECT_LT(w.rayCast({0, 0, 1.0}, {0, 0, 1}, 5.0, -1), 0);  // nothing above
}

TEST(Ball, BallBlowUpIsResetAndReported) {
  World w(FieldConfig::spl2017());
  w.placeBall(1.0, 1.0);
  w.step();
  EXPECT_TRUE(w.takeEvents().empty());
  EXPECT_THROW(w.setBallVelocity({1e6, 0, 0}), WorldError);  // refused through the API
  dBodySetLinearVel(w.ballBody(), 1e6, 0, 0);                 // so written past it
  w.step();
  auto ev = w.takeEvents();
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].kind, WorldEvent::Kind::BlowUp);
  EXPECT_EQ(ev[0].robot, -1);
  EXPECT_NE(ev[0].message.find("ball"), std::string::npos);
  // Reset before the tick's first substep, then at rest for one tick: only
  // the contact layer's settling (mm/s) remains.
  EXPECT_NEAR(w.ballPosition().x(), 1.0, 1e-6);
  EXPECT_LT(w.ballVelocity().norm(), 1e-3);
}

TEST(Ball, RemovedBallNeitherMovesNorCollides) {
  // `ball: none`: the disabled body stays exactly where it was, however it
  // was moving, and no contact or gravity acts on it.
  World w(splField());
  w.placeBall(0.0, 0.0);
  w.setBallVelocity(Eigen::Vector3d(2.0, 0.0, 0.0));
  w.removeBall();
  EXPECT_FALSE(w.hasBall());
  const Eigen::Vector3d before = w.ballPosition();
  run(w, 0.5);
  EXPECT_EQ(w.ballPosition(), before);
  EXPECT_EQ(w.ballVelocity().norm(), 0.0);
}
