// The robot code's camera matrix (agent/perception/CameraMatrix: joint
// angles + inertial tilt + the NAO hardware facts) against the simulator's
// true camera pose (sim/camera CameraModel on the physics body): the same
// camera position and optical axis in the robot frame, for both cameras,
// with the head turned and the robot leaning.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "agent/perception/CameraMatrix.hpp"
#include "agent/program/Postures.hpp"
#include "sim/camera/CameraModel.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/sensors/SensorSuite.hpp"
#include "sim/world/World.hpp"
#include "tests/support/NaoV5Model.hpp"

using namespace simswift;
namespace ape = agent::perception;

namespace {
using simswift::testing::naoV5Model;
}  // namespace

TEST(CameraMatrix, MatchesTheSimulatedCameraPose) {
  for (auto [yaw, pitch, knee_extra] : {std::tuple{0.0, 0.0, 0.0}, std::tuple{0.5, 0.25, 0.0},
                                        std::tuple{-0.8, -0.3, 0.15}}) {
    World world(FieldConfig::spl2017());
    const RobotModel& m = *naoV5Model();
    std::vector<double> q = simswift::NaoBinding(m).posture(agent::program::postureAngles(agent::program::Posture::Stand));
    q[m.jointIndex("HeadYaw")] = yaw;
    q[m.jointIndex("HeadPitch")] = pitch;
    // Bend one knee a little more: the torso tilts and the feet differ.
    q[m.jointIndex("LKneePitch")] += knee_extra;
    q[m.jointIndex("LAnklePitch")] -= knee_extra / 2;
    const int r = world.addRobot(naoV5Model(), -1.0, 0.5, 0.7, q);
    world.robot(r).holdPosture(q, 1.0f);
    sensors::SensorConfig sc;
    sc.noise = false;
    sensors::SensorSuite suite(world, r, sc);
    for (int i = 0; i < 100; ++i) {
      world.step();
      suite.update(world);
    }
    common::libagent::SensorValues v{};
    sensors::copyToAgent(suite.reading(), v);

    // The robot frame in the world: midway between the soles, on the lower
    // one, heading along the torso's x axis.
    const RobotBody& body = world.robot(r);
    const Eigen::Vector3d sole_offset(0, 0, -common::nao::links::kFootHeight * 1e-3);
    const Eigen::Vector3d ls = body.linkPose(m.linkIndex("LFoot")) * sole_offset;
    const Eigen::Vector3d rs = body.linkPose(m.linkIndex("RFoot")) * sole_offset;
    const Eigen::Vector3d fwd = body.linkPose(m.rootLink()).linear().col(0);
    const double heading = std::atan2(fwd.y(), fwd.x());
    const Eigen::Matrix3d to_robot = Eigen::AngleAxisd(-heading, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d origin(0.5 * (ls.x() + rs.x()), 0.5 * (ls.y() + rs.y()), std::min(ls.z(), rs.z()));

    for (auto [agent_cam, sim_cam] : {std::pair{common::nao::Camera::Top, camera::kTop},
                                      std::pair{common::nao::Camera::Bottom, camera::kBottom}}) {
      const camera::CameraModel truth = camera::CameraModel::naoCamera(body.linkPose(m.linkIndex("Head")), sim_cam);
      const Eigen::Vector3d p = to_robot * (truth.pose.translation() - origin) * 1000.0;  // mm
      const Eigen::Vector3d axis = to_robot * truth.pose.linear().col(0);
      const ape::CameraPose est = ape::cameraPose(v, agent_cam);
      const Eigen::Vector3d ep(est.position.x, est.position.y, est.position.z);
      const Eigen::Vector3d ea(est.rotation.m[0][0], est.rotation.m[1][0], est.rotation.m[2][0]);
      // Tolerances: encoder quantisation and the servos' small tracking error
      // move the camera by millimetres; the tilt from the inertial unit is
      // exact with noise off.
      EXPECT_LT((ep - p).norm(), 8.0) << "yaw " << yaw << " pitch " << pitch << ": " << ep.transpose() << " vs "
                                      << p.transpose();
      EXPECT_LT(std::acos(std::min(1.0, ea.dot(axis))), 1.0 * M_PI / 180) << "yaw " << yaw << " pitch " << pitch;
      // A point straight along the optical axis on the ground is in view; one
      // behind the robot is not.
      if (axis.z() < -0.05) {
        const double t = -p.z() / (1000.0 * axis.z()) * 1000.0;
        EXPECT_TRUE(ape::inFieldOfView(est, p.x() + t * axis.x(), p.y() + t * axis.y()));
      }
      EXPECT_FALSE(ape::inFieldOfView(est, -2000, 0));
    }
  }
}
