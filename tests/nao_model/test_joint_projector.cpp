// JointProjector: hinge anchors pulled apart come back together, mass
// weighted, and pinned links stay where they are. Units: m, kg.
#include <gtest/gtest.h>
#include <ode/ode.h>

#include <Eigen/Core>
#include <mutex>

#include "sim/nao_model/JointProjector.hpp"

using simswift::JointProjector;

namespace {

Eigen::Vector3d position(dBodyID b) {
  const dReal* p = dBodyGetPosition(b);
  return {p[0], p[1], p[2]};
}

// Two boxes (1 kg and 0.25 kg, 0.1 m cubes) in a row along x, hinged at the
// point between them; then the light one is moved 2 mm off along y and z.
struct TwoLinks {
  dWorldID world;
  dBodyID heavy, light;
  std::unique_ptr<JointProjector> projector;
  TwoLinks() {
    static std::once_flag once;
    std::call_once(once, [] { dInitODE2(0); });
    world = dWorldCreate();
    heavy = box(1.0, 0.0);
    light = box(0.25, 0.1);
    // Hinge at x = 0.05: 0.05 m from each CoM.
    projector = std::make_unique<JointProjector>(
        std::vector<dBodyID>{heavy, light},
        std::vector<JointProjector::Hinge>{{1, 0, Eigen::Vector3d(-0.05, 0, 0), Eigen::Vector3d(0.05, 0, 0)}});
    dBodySetPosition(light, 0.1, 0.002, -0.002);
  }
  ~TwoLinks() { dWorldDestroy(world); }
  dBodyID box(double kg, double x) {
    dBodyID b = dBodyCreate(world);
    dMass m;
    dMassSetBoxTotal(&m, kg, 0.1, 0.1, 0.1);
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, 0, 0);
    return b;
  }
  double separation() const {  // m, between the anchor as each body carries it
    const dReal* rh = dBodyGetRotation(heavy);
    const dReal* rl = dBodyGetRotation(light);
    const Eigen::Vector3d ah = position(heavy) + Eigen::Vector3d(rh[0], rh[4], rh[8]) * 0.05;
    const Eigen::Vector3d al = position(light) - Eigen::Vector3d(rl[0], rl[4], rl[8]) * 0.05;
    return (ah - al).norm();
  }
};

}  // namespace

TEST(JointProjector, BringsAnchorsTogetherAndKeepsTheMassCentre) {
  TwoLinks t;
  ASSERT_NEAR(t.separation(), 0.002 * std::sqrt(2.0), 1e-9);
  const Eigen::Vector3d centre = (1.0 * position(t.heavy) + 0.25 * position(t.light)) / 1.25;
  const double left = t.projector->project({0, 0}, 16, 1e-6);
  EXPECT_LT(left, 1e-6);
  EXPECT_LT(t.separation(), 1e-6);
  // A positional pass moves no mass centre: the light box moved about 4x as far.
  const Eigen::Vector3d after = (1.0 * position(t.heavy) + 0.25 * position(t.light)) / 1.25;
  EXPECT_LT((after - centre).norm(), 1e-9);
  EXPECT_GT((position(t.light) - Eigen::Vector3d(0.1, 0.002, -0.002)).norm(),
            2.0 * (position(t.heavy) - Eigen::Vector3d::Zero()).norm());
}

TEST(JointProjector, PinnedLinkStaysAndTheOtherComesToIt) {
  TwoLinks t;
  t.projector->project({1, 0}, 16, 1e-6);  // the heavy box is pinned
  EXPECT_LT(t.separation(), 1e-6);
  EXPECT_LT(position(t.heavy).norm(), 1e-12);
  // Both pinned: nothing can move, the gap is reported as it is.
  TwoLinks u;
  const double left = u.projector->project({1, 1}, 16, 1e-6);
  EXPECT_NEAR(left, 0.002 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(position(u.light).y(), 0.002, 1e-12);
}
