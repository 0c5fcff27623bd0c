// A robot as an immutable description, loaded once from any URDF: links
// with their masses, inertias and shapes, and limited hinge joints.
//
// This is the "model" half of a MuJoCo-style split: nothing here changes
// while a simulation runs. RobotBody (RobotBody.hpp) instantiates it into an
// ODE world as mutable state. Nothing here is NAO-specific: a single box or
// a pendulum loads as well as the NAO. What makes a model a NAO that
// libagent can drive (its 25 libagent joints) is checked apart, when a robot
// is attached to libagent (NaoBinding.hpp).
//
// Units: m, kg, kg*m^2, rad, rad/s, N*m. Frames: every pose is relative to
// the parent link's frame, as in URDF (x forward, y left, z up for the NAO
// in its zero posture).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace simswift {

// A rigid transform (URDF <origin xyz rpy>).
struct Pose3 {
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Isometry3d isometry() const;
};

enum class ShapeType { Box, Sphere, Cylinder, Capsule, Mesh };

// One collision or visual shape, in its link's frame.
struct ShapeSpec {
  ShapeType type = ShapeType::Box;
  Pose3 origin;
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  // box: full extents (m)
  double radius = 0;                               // sphere, cylinder, capsule (m)
  double length = 0;                               // cylinder, capsule: along local z (m)
  std::string mesh;                                // mesh file (visual only)
  Eigen::Vector4d rgba{0.8, 0.8, 0.8, 1.0};        // visual colour
};

struct LinkSpec {
  std::string name;
  double mass = 0;                                  // kg
  Pose3 inertial_origin;                            // CoM pose in the link frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero(); // about the CoM, in inertial_origin axes
  std::vector<ShapeSpec> collisions;
  std::vector<ShapeSpec> visuals;
  int parent_joint = -1;                            // index into joints, -1 for the root (torso)
};

struct JointSpec {
  std::string name;
  int parent_link = -1;
  int child_link = -1;
  Pose3 origin;                     // child frame in the parent frame at angle 0
  Eigen::Vector3d axis{0, 0, 1};    // unit, in the child (joint) frame
  double lower = 0, upper = 0;      // rad (Hand: 0..1 fraction open, mapped to an angle range)
  double max_velocity = 0;          // rad/s
  double max_effort = 0;            // N*m at stiffness 1
  std::optional<std::string> mimic; // RHipYawPitch mimics LHipYawPitch
  double mimic_multiplier = 1.0;
  // Lines in the source of the <joint> and of its <mimic> (the joint's line
  // if none): later checks (NaoBinding) quote them.
  int line = 1, mimic_line = 1;
};

// Raised for a missing or malformed element; the message names the file and
// the link or joint: "file:line: what", the file and line also kept apart.
struct ModelError : std::runtime_error {
  ModelError(std::string file_, int line_, const std::string& what)
      : std::runtime_error(file_ + ":" + std::to_string(line_) + ": " + what), file(std::move(file_)), line(line_) {}

  std::string file;
  int line = 0;
};

class RobotModel {
 public:
  // Loads and validates a URDF (urdfdom): every link has a mass and a rigid
  // body's inertia, every joint is a limited hinge, every mimic follows a
  // joint that is not itself a mimic. Throws ModelError "source:line: ...".
  static RobotModel loadUrdf(const std::string& path);
  static RobotModel loadUrdfString(const std::string& xml, const std::string& source_name);

  const std::vector<LinkSpec>& links() const { return links_; }
  const std::vector<JointSpec>& joints() const { return joints_; }
  int linkIndex(const std::string& name) const;   // -1 if absent
  int jointIndex(const std::string& name) const;  // -1 if absent
  int rootLink() const { return root_; }
  double totalMass() const;                        // kg
  // Where it was loaded from (the file name, or the name given with the
  // string) and the line of its <robot> element: for later errors.
  const std::string& source() const { return source_; }
  int robotLine() const { return robot_line_; }

 private:
  std::vector<LinkSpec> links_;
  std::vector<JointSpec> joints_;
  int root_ = -1;
  std::string source_;
  int robot_line_ = 1;
};

}  // namespace simswift
