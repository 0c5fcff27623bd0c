// Keeps a robot's hinge anchors together: a position pass after each physics
// substep (the non-linear Gauss-Seidel position correction of Box2D's solver).
//
// Why: QuickStep solves the joint rows only approximately (20 iterations of
// projected Gauss-Seidel over a chain of light links between a 1 kg torso
// and a loaded foot), so under walking loads the hinge anchors of the hip
// and ankle joints come apart by up to about 1 mm, and ERP only pulls them
// back over the next steps. This pass moves the bodies themselves, mass
// weighted, so that every hinge's anchor as seen from its child meets the
// one seen from its parent; velocities are left to the solver. The caller
// pins the links that must not move (the World: feet standing on their
// soles, which their friction holds), so the correction never slides a
// standing foot; a pass between two pinned links may not close fully.
//
// Units: m, kg, kg m^2; world frame.
#pragma once

#include <ode/ode.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace simswift {

class JointProjector {
 public:
  struct Hinge {
    int child, parent;          // link indices
    Eigen::Vector3d at_child;   // anchor in the child body's frame (m, from its CoM)
    Eigen::Vector3d at_parent;  // anchor in the parent body's frame (m)
  };
  // `bodies` per link; each hinge's anchor is taken as it stands now (the
  // bodies must be assembled, as right after construction).
  JointProjector(const std::vector<dBodyID>& bodies, const std::vector<Hinge>& hinges);

  // Up to `sweeps` Gauss-Seidel sweeps over the hinges, stopping once no
  // anchor pair is farther apart than `tolerance` (m); links with
  // pinned[link] != 0 do not move. Returns the largest separation left (m).
  double project(const std::vector<char>& pinned, int sweeps, double tolerance);

 private:
  std::vector<dBodyID> bodies_;
  std::vector<Hinge> hinges_;
  std::vector<double> inv_mass_;                // 1/kg per link
  std::vector<Eigen::Matrix3d> inv_inertia_;    // body frame, 1/(kg m^2)
  // Scratch for one pass, per link: position, orientation (as quaternion
  // and matrix), inverse mass and world inverse inertia (0 when pinned).
  std::vector<Eigen::Vector3d> x_;
  std::vector<Eigen::Quaterniond> q_;
  std::vector<Eigen::Matrix3d> r_;
  std::vector<double> w_;
  std::vector<Eigen::Matrix3d> iw_;
  // Whether iw_[l] is current for r_[l], or is to be computed (lazily).
  enum : char { kCurrent, kFromStart, kTurned };
  std::vector<char> iw_state_;
  std::vector<char> moved_;
};

}  // namespace simswift
