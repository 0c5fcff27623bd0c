// The production World (default WorldConfig: QuickStep, 2 substeps of 5 ms
// per 10 ms tick) on tiny inline URDF models, MuJoCo-style: physics checked
// against the textbook on a system small enough to know the answer. A 1 kg
// box resting on the carpet, and a one-hinge pendulum swinging from a pivot
// held in the air. Units: m, kg, s, N, rad; field frame (z up).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "sim/world/World.hpp"

using namespace simswift;

namespace {

constexpr double kG = 9.81;  // m/s^2, WorldConfig::gravity

// A 1 kg, 0.1 m cube (I = m a^2 / 6 = 1.67e-3 kg*m^2 about every axis).
const char* kBoxUrdf = R"(<robot name="box">
  <link name="box">
    <inertial><mass value="1"/>
      <inertia ixx="1.6667e-3" iyy="1.6667e-3" izz="1.6667e-3" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
  </link>
</robot>)";

// A pendulum: a 1 kg bob (a 2 cm sphere) hanging kLength below a hinge about
// y. The hinge's velocity limit is tiny because a limp joint keeps a
// friction torque of ServoConfig::limp_damping (0.02) x that limit: here
// 2e-4 N*m, 0.04 % of gravity's torque on the bob at 0.1 rad.
constexpr double kLength = 0.5;  // m, pivot to the bob's centre of mass
std::string pendulumUrdf(double lower, double upper) {
  return R"(<robot name="pendulum">
  <link name="pivot">
    <inertial><mass value="1"/>
      <inertia ixx="1e-3" iyy="1e-3" izz="1e-3" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.04 0.04 0.04"/></geometry></collision>
  </link>
  <joint name="swing" type="revolute">
    <parent link="pivot"/><child link="bob"/>
    <origin xyz="0 0 0"/><axis xyz="0 1 0"/>
    <limit lower=")" + std::to_string(lower) + R"(" upper=")" + std::to_string(upper) +
         R"(" velocity="0.01" effort="1"/>
  </joint>
  <link name="bob">
    <inertial><origin xyz="0 0 -0.5"/><mass value="1"/>
      <inertia ixx="1e-4" iyy="1e-4" izz="1e-4" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 -0.5"/><geometry><sphere radius="0.02"/></geometry></collision>
  </link>
</robot>)";
}

std::shared_ptr<const RobotModel> load(const std::string& xml, const char* name) {
  return std::make_shared<const RobotModel>(RobotModel::loadUrdfString(xml, name));
}

// Sum of the tick-average contact forces on robot `robot` (N, world frame).
Eigen::Vector3d contactForce(const World& w, int robot) {
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  for (const LinkContact& c : w.contacts())
    if (c.robot == robot) f += c.force;
  return f;
}

// A pendulum whose pivot is held 1 m above the carpet by a fixed joint to
// the world (a test rig: the World has no fixed bases), the bob released at
// `angle` rad, limp.
struct Pendulum {
  World w{FieldConfig::spl2017()};
  int i = -1;
  Pendulum(const std::shared_ptr<const RobotModel>& model, double angle) {
    w.removeBall();
    i = w.addRobot(model, 0.0, 0.0, 0.0, {angle});
    Eigen::Isometry3d pivot = Eigen::Isometry3d::Identity();
    pivot.translation() = Eigen::Vector3d(0, 0, 1.0);
    w.robot(i).teleport(pivot);
    dJointID fixed = dJointCreateFixed(w.odeWorld(), nullptr);
    dJointAttach(fixed, w.robot(i).torsoBody(), nullptr);
    dJointSetFixed(fixed);
  }
  double angle() const { return w.robot(i).jointAngle(0); }
};

}  // namespace

TEST(TinyModels, BoxLoadsAsAOneLinkRobot) {
  const auto box = load(kBoxUrdf, "box.urdf");
  EXPECT_EQ(box->links().size(), 1u);
  EXPECT_TRUE(box->joints().empty());
  EXPECT_DOUBLE_EQ(box->totalMass(), 1.0);
  World w(FieldConfig::spl2017());
  const int i = w.addRobot(box, 1.0, 1.0, 0.0, {});
  EXPECT_NEAR(w.robot(i).lowestPoint(), 0.0, 1e-9);  // placed on the carpet
  EXPECT_NEAR(w.robot(i).torsoPose().z, 0.05, 1e-9);  // its centre half an edge up
}

// At rest the carpet carries exactly the box's weight. The contact rows
// are solved iteratively (QuickStep, 20 iterations), but a box at rest on
// four corner contacts converges: measured within 0.1 % of m g on every
// tick, so 1 % (0.1 N) leaves room without letting a wrong mass, gravity or
// contact scaling (each 10 % or more) through. Drift: friction holds the
// box in place, measured to micrometres over 10 s: 0.1 mm allowed. Height:
// contacts push back only beyond the 1 mm surface layer (World.cpp), and
// QuickStep's residual lets a resting box sink into it slowly (0.3 mm after
// 1 s, 0.5 mm after 11 s, measured): it must stay within the layer.
TEST(TinyModels, BoxRestingOnTheCarpetPressesItsWeightAndStaysPut) {
  World w(FieldConfig::spl2017());
  const int i = w.addRobot(load(kBoxUrdf, "box.urdf"), 1.0, 1.0, 0.3, {});
  for (int k = 0; k < 100; ++k) w.step();  // 1 s: settle into the contact layer
  const RobotBody::TorsoPose p0 = w.robot(i).torsoPose();
  double worst = 0;  // N, largest |vertical force - m g| over the ticks
  for (int k = 0; k < 1000; ++k) {  // 10 s
    w.step();
    const Eigen::Vector3d f = contactForce(w, i);
    worst = std::max(worst, std::fabs(f.z() - 1.0 * kG));
    ASSERT_LT(std::hypot(f.x(), f.y()), 0.01 * kG) << "tick " << k;  // nothing pushes it sideways
  }
  EXPECT_LT(worst, 0.01 * kG) << "vertical contact force off m g by up to " << worst << " N";
  const RobotBody::TorsoPose p1 = w.robot(i).torsoPose();
  EXPECT_LT(std::hypot(p1.x - p0.x, p1.y - p0.y), 1e-4);  // m
  const double layer = 0.001;                              // m, World.cpp
  EXPECT_GE(p1.z, 0.05 - layer);                           // m: half an edge up, less the layer
  EXPECT_LE(p1.z, p0.z + 1e-6);                            // m: never rises
  EXPECT_NEAR(p1.heading, p0.heading, 1e-3);              // rad
  EXPECT_TRUE(w.takeEvents().empty());
}

// Released from 0.1 rad the bob swings with the small-angle period
// T0 = 2 pi sqrt(L / g) (1.419 s for L = 0.5 m). What separates the
// simulation from T0, each term computed below:
//   - the bob's own inertia: RobotBody raises every principal moment to
//     ServoConfig::min_link_inertia (5e-4 kg*m^2), so the bob is a
//     physical pendulum, T = T0 sqrt(1 + I / (m L^2)): +0.10 %;
//   - the amplitude: T = T0 (1 + theta0^2 / 16 + ...): +0.06 % at 0.1 rad;
//   - the integrator: ODE's semi-implicit Euler at the substep h runs an
//     oscillator of angular frequency w with a period off by (w h)^2 / 24,
//     2e-5 at h = 5 ms;
//   - the measurement: each zero crossing is found by linear interpolation
//     between ticks (10 ms), off by at most (w dt)^2 / 8 of a tick, and the
//     period is the span of 5 whole periods, so it is off by at most
//     2 x that / 5;
//   - the solver: QuickStep's residual on the hinge and the rig's fixed
//     joint, not modelled: 1e-4 allowed (measured 2.5e-5 beyond the terms
//     above).
// The tolerance is their sum (0.18 %): a wrong length, gravity or a hinge
// on the wrong axis (a period off by a per cent or more) fails it.
TEST(TinyModels, PendulumSwingsWithTheSmallAnglePeriod) {
  const double theta0 = 0.1;  // rad
  Pendulum p(load(pendulumUrdf(-1.5, 1.5), "pendulum.urdf"), theta0);
  EXPECT_NEAR(p.angle(), theta0, 1e-9);
  const double t0 = 2 * M_PI * std::sqrt(kLength / kG);  // s
  const double w = 2 * M_PI / t0;                         // rad/s
  const double h = kTickSeconds / WorldConfig{}.substepsPerTick();  // s, one substep
  const double m = 1.0, inertia = ServoConfig{}.min_link_inertia;
  const int periods = 5;
  const double tolerance = (std::sqrt(1 + inertia / (m * kLength * kLength)) - 1) + theta0 * theta0 / 16 +
                           (w * h) * (w * h) / 24 +
                           2 * (w * kTickSeconds) * (w * kTickSeconds) / 8 * kTickSeconds / (periods * t0) + 1e-4;
  // Times (s) the angle crosses 0 going up, linearly interpolated.
  std::vector<double> ups;
  double prev = p.angle();
  for (int k = 1; k <= 1000 && static_cast<int>(ups.size()) <= periods; ++k) {
    p.w.step();
    const double a = p.angle();
    if (prev < 0 && a >= 0) ups.push_back((k - 1 + prev / (prev - a)) * kTickSeconds);
    prev = a;
  }
  ASSERT_EQ(static_cast<int>(ups.size()), periods + 1) << "the pendulum did not swing";
  const double period = (ups.back() - ups.front()) / periods;
  std::printf("[tiny] pendulum period %.5f s, small-angle %.5f s (%+.3f %%, tolerance %.3f %%)\n", period, t0,
              (period / t0 - 1) * 100, tolerance * 100);
  EXPECT_NEAR(period, t0, tolerance * t0);
  // The pivot stayed put: the fixed joint holds it to a fraction of a mm.
  EXPECT_NEAR(p.w.robot(p.i).torsoPose().z, 1.0, 1e-3);
  EXPECT_TRUE(p.w.takeEvents().empty());
}
