#include "sim/nao_model/JointProjector.hpp"

#include <Eigen/Geometry>
#include <algorithm>

namespace simswift {

namespace {
Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}
}  // namespace

JointProjector::JointProjector(const std::vector<dBodyID>& bodies, const std::vector<Hinge>& hinges)
    : bodies_(bodies), hinges_(hinges), inv_mass_(bodies.size()), inv_inertia_(bodies.size()),
      x_(bodies.size()), q_(bodies.size()), r_(bodies.size()), w_(bodies.size()), iw_(bodies.size()),
      iw_state_(bodies.size()), moved_(bodies.size()) {
  for (size_t l = 0; l < bodies_.size(); ++l) {
    dMass m;
    dBodyGetMass(bodies_[l], &m);
    inv_mass_[l] = 1.0 / m.mass;
    Eigen::Matrix3d inertia;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) inertia(r, c) = m.I[4 * r + c];
    inv_inertia_[l] = inertia.inverse();
  }
}

double JointProjector::project(const std::vector<char>& pinned, int sweeps, double tolerance) {
  const size_t n = bodies_.size();
  for (size_t l = 0; l < n; ++l) {
    const dReal* p = dBodyGetPosition(bodies_[l]);
    const dReal* q = dBodyGetQuaternion(bodies_[l]);  // w, x, y, z
    x_[l] = Eigen::Vector3d(p[0], p[1], p[2]);
    q_[l] = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
    r_[l] = q_[l].toRotationMatrix();
    const bool fixed = l < pinned.size() && pinned[l];
    w_[l] = fixed ? 0.0 : inv_mass_[l];
    // The world inverse inertia is computed when a correction first needs
    // it (most substeps most hinges are within the tolerance already).
    if (fixed) iw_[l].setZero();
    iw_state_[l] = fixed ? kCurrent : kFromStart;
    moved_[l] = 0;
  }
  auto inverseInertia = [&](int l) -> const Eigen::Matrix3d& {
    // The two forms are the ones the eager version used (at the start and
    // after a turn); Eigen evaluates them differently in the last bit, and
    // the lazy pass must give bit for bit the same result.
    if (iw_state_[l] == kFromStart) {
      iw_[l] = Eigen::Matrix3d(r_[l] * inv_inertia_[l] * r_[l].transpose());
    } else if (iw_state_[l] == kTurned) {
      iw_[l] = r_[l] * inv_inertia_[l] * r_[l].transpose();
    }
    iw_state_[l] = kCurrent;
    return iw_[l];
  };
  // A small rotation dtheta (rad, world frame) of link l.
  auto turn = [&](int l, const Eigen::Vector3d& dtheta) {
    Eigen::Quaterniond& q = q_[l];
    q.coeffs() += 0.5 * (Eigen::Quaterniond(0, dtheta.x(), dtheta.y(), dtheta.z()) * q).coeffs();
    q.normalize();
    r_[l] = q.toRotationMatrix();
    iw_state_[l] = kTurned;
    moved_[l] = 1;
  };
  double worst = 0;
  for (int sweep = 0; sweep <= sweeps; ++sweep) {
    worst = 0;
    for (const Hinge& h : hinges_) {
      const Eigen::Vector3d arm_c = r_[h.child] * h.at_child, arm_p = r_[h.parent] * h.at_parent;
      const Eigen::Vector3d error = (x_[h.child] + arm_c) - (x_[h.parent] + arm_p);  // m
      const double e = error.norm();
      worst = std::max(worst, e);
      if (sweep == sweeps || e <= tolerance) continue;
      const double wc = w_[h.child], wp = w_[h.parent];
      if (wc == 0 && wp == 0) continue;
      // Effective inverse mass of the anchor pair (3 x 3) and the positional
      // "impulse" that closes the gap: K lambda = error.
      const Eigen::Matrix3d sc = skew(arm_c), sp = skew(arm_p);
      const Eigen::Matrix3d& iwc = inverseInertia(h.child);
      const Eigen::Matrix3d& iwp = inverseInertia(h.parent);
      const Eigen::Matrix3d k = (wc + wp) * Eigen::Matrix3d::Identity() - sc * iwc * sc - sp * iwp * sp;
      const Eigen::Vector3d lambda = k.inverse() * error;
      if (wc > 0) {
        x_[h.child] -= wc * lambda;
        turn(h.child, -(iwc * arm_c.cross(lambda)));
      }
      if (wp > 0) {
        x_[h.parent] += wp * lambda;
        turn(h.parent, iwp * arm_p.cross(lambda));
      }
    }
    if (worst <= tolerance) break;
  }
  for (size_t l = 0; l < n; ++l) {
    if (!moved_[l]) continue;
    dBodySetPosition(bodies_[l], x_[l].x(), x_[l].y(), x_[l].z());
    const dQuaternion q = {q_[l].w(), q_[l].x(), q_[l].y(), q_[l].z()};
    dBodySetQuaternion(bodies_[l], q);
  }
  return worst;
}

}  // namespace simswift
