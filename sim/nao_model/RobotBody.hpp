// One simulated robot (the NAO, or any RobotModel: a box, a pendulum): the
// model instantiated as ODE bodies, geoms and hinge joints, plus its joint
// servos (the DCM's behaviour). Mutable state; the model it was built from
// is shared and immutable. Commands here are in model joint order; libagent's
// 25 slots reach them through NaoBinding (NaoBinding.hpp).
//
// Units: m, rad, rad/s, N, N*m. Poses are in the world (field) frame: origin
// at the centre spot, x toward the opponent goal, y left, z up.
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "sim/nao_model/JointProjector.hpp"
#include "sim/nao_model/RobotModel.hpp"
#include "sim/nao_model/Servo.hpp"

namespace simswift {

// What ODE geoms carry in their user data, so contacts can be attributed.
struct GeomTag {
  enum Kind : int32_t { Ground, FieldObject, Net, Ball, RobotLink } kind = Ground;
  int32_t robot = -1;  // robot index for RobotLink
  int32_t link = -1;   // link index in the RobotModel for RobotLink
  // A foot's sole box (the box collision shape of the link below an
  // AnkleRoll joint): the world gives its ground contact as a patch of points
  // over the whole sole instead of the box's corners (Contacts.cpp).
  bool sole = false;
};

class RobotBody {
 public:
  // rad: the hinges' stops lie this far outside each joint's limits (the
  // range servo targets are clamped to); see RobotBody.cpp.
  static constexpr double kStopBeyondLimit = 0.01;

  // Builds bodies/geoms/joints in `world`/`space` with the torso at
  // `torso_pose` and all joints at `posture` (rad, indexed like
  // model.joints(); missing entries = 0; clamped to the limits).
  // Geoms go straight into `space`, each tagged (GeomTag) with this robot's
  // index and its link: the world's collision callback must skip pairs whose
  // tags name the same robot (no self-collision). Destroy every RobotBody
  // before its dWorldID. Link inertias get ServoConfig::min_link_inertia.
  RobotBody(const RobotModel& model, int robot_index, dWorldID world, dSpaceID space,
            const Eigen::Isometry3d& torso_pose, const std::vector<double>& posture,
            const ServoConfig& servo_config);
  ~RobotBody();
  RobotBody(const RobotBody&) = delete;
  RobotBody& operator=(const RobotBody&) = delete;

  const RobotModel& model() const { return *model_; }
  int index() const { return index_; }

  // --- Commands (model joint order). Latched; the runner decides when they
  // take effect (one 10 ms cycle after they were written).
  // One joint's servo target (rad) and stiffness (0..1; <= 0 limp); the
  // joints that mimic it follow (RHipYawPitch follows LHipYawPitch).
  void setTarget(int joint, double angle, double stiffness);
  // Every joint but the mimics to `posture` (rad; missing entries 0) at
  // `stiffness`. The angles pass through float, as libagent's commands do,
  // so a held posture is the same posture commanded through libagent.
  void holdPosture(const std::vector<double>& posture, float stiffness = 1.0f);
  const ServoCommandStats& commandStats() const { return servo_.stats(); }

  // Called by the World before every physics substep of length dt (s).
  void applyServos(double dt);

  // --- State
  double jointAngle(int joint) const;     // rad, model joint index
  double jointVelocity(int joint) const;  // rad/s
  double jointTorque(int joint) const;    // N*m last applied by the servo
  double jointCurrent(int joint) const { return servo_.current(joint); }          // A, motor
  double jointTemperature(int joint) const { return servo_.temperature(joint); }  // deg C
  const ServoBank& servos() const { return servo_; }
  // Largest distance (m) between a hinge's anchor as seen from its child and
  // from its parent: how far the joint constraints give under load.
  double anchorSeparation() const;
  // Called by the World after every physics substep: moves the links so the
  // hinge anchors meet again (JointProjector); links with pinned[link] set
  // (touching the ground) stay. Returns the largest separation left (m).
  double projectJoints(const std::vector<char>& pinned, int sweeps, double tolerance) {
    return projector_->project(pinned, sweeps, tolerance);
  }
  dBodyID body(int link) const { return bodies_[link]; }
  dBodyID torsoBody() const { return bodies_[model_->rootLink()]; }
  Eigen::Isometry3d linkPose(int link) const;            // link frame in world
  // The torso's origin (m) and the heading of its x axis (rad, atan2 of its
  // projection on the ground), field frame: where a robot "is".
  struct TorsoPose {
    double x = 0, y = 0, z = 0;
    double heading = 0;
  };
  TorsoPose torsoPose() const;
  Eigen::Vector3d linkLinearVelocity(int link, const Eigen::Vector3d& point_in_link) const;
  Eigen::Vector3d linkAngularVelocity(int link) const;   // world frame
  const std::vector<dGeomID>& geoms() const { return geoms_; }

  // --- Teleport: moves the whole robot rigidly so the torso is at `pose`,
  // zeroing all velocities. With a posture, joints are set first.
  void teleport(const Eigen::Isometry3d& torso_pose);
  void setPosture(const std::vector<double>& posture);  // kinematic, keeps torso pose

  // Lowest z of any collision geom (m) -- used to put the feet on the ground.
  double lowestPoint() const;

  // True if any body has a NaN/inf or speed beyond the limits (m/s, rad/s).
  bool blownUp(double max_linear, double max_angular) const;

 private:
  const RobotModel* model_;
  int index_;
  dWorldID world_;
  std::vector<dBodyID> bodies_;        // per link
  std::vector<dJointID> joints_;       // per joint (hinge)
  std::vector<dGeomID> geoms_;
  std::vector<std::unique_ptr<GeomTag>> tags_;
  ServoBank servo_;
  // Each link's centre of mass in its link frame (m): ODE puts a body's
  // origin at its CoM, so link frame = body frame shifted by -com.
  std::vector<Eigen::Vector3d> com_;
  std::vector<dJointFeedback> feedback_;  // per joint, filled by ODE each step
  std::vector<double> motor_cap_;         // per joint, the motor's torque cap last substep (N*m)
  std::unique_ptr<JointProjector> projector_;
  std::vector<std::vector<int>> followers_;  // per joint: the joints that mimic it
  // Link frames in the world for torso pose `torso` and joint angles (rad).
  std::vector<Eigen::Isometry3d> forwardKinematics(const Eigen::Isometry3d& torso,
                                                   const std::vector<double>& angles) const;
  void placeLinks(const std::vector<Eigen::Isometry3d>& poses);
};

}  // namespace simswift
