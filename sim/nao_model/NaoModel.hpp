// The NAO V5 as an immutable description, loaded once from the URDF.
//
// This is the "model" half of a MuJoCo-style split: nothing here changes
// while a simulation runs. RobotBody (RobotBody.hpp) instantiates it into an
// ODE world as mutable state. Units: m, kg, kg*m^2, rad, rad/s, N*m. Frames:
// every pose is relative to the parent link's frame, as in URDF (x forward,
// y left, z up for the NAO in its zero posture).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "agent/libagent/AgentShared.hpp"  // kNumJoints: the 25 libagent joints

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
  int libagent_index = -1;          // slot in the 25-joint libagent order, -1 if none
};

// Raised for a missing or malformed element; the message names the file and
// the link or joint.
struct ModelError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class NaoModel {
 public:
  // Loads and validates a URDF (urdfdom). Throws ModelError.
  static NaoModel loadUrdf(const std::string& path);
  static NaoModel loadUrdfString(const std::string& xml, const std::string& source_name);

  const std::vector<LinkSpec>& links() const { return links_; }
  const std::vector<JointSpec>& joints() const { return joints_; }
  int linkIndex(const std::string& name) const;   // -1 if absent
  int jointIndex(const std::string& name) const;  // -1 if absent
  int rootLink() const { return root_; }
  double totalMass() const;                        // kg

  // The joint driven by libagent slot i (0..24).
  int jointForLibagent(int i) const { return libagent_to_joint_[i]; }

  // A posture in model joint order from 25 libagent-order angles (rad);
  // mimicking joints (RHipYawPitch) copy the joint they follow.
  std::vector<double> postureFromLibagent(const std::array<float, agent::libagent::kNumJoints>& angles) const;

 private:
  std::vector<LinkSpec> links_;
  std::vector<JointSpec> joints_;
  int root_ = -1;
  std::array<int, agent::libagent::kNumJoints> libagent_to_joint_{};
};

}  // namespace simswift
